// The `relight` command: every subcommand lives in src/cli/.
#include "cli/cli.h"

int main(int argc, char** argv) {
  return relight::run_cli(argc, argv);
}
