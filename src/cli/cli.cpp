#include "cli/cli.h"

#include <iostream>

namespace relight {

int run_cli(int, char**) {
  std::cerr << "error: not implemented yet\n";
  return 1;
}

}  // namespace relight
