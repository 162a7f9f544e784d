#include "common/input_error.h"

namespace relight {

void fail_input(const std::string& where, const std::string& reason) {
  throw InputError(where + ": " + reason);
}

std::string at_line(const std::filesystem::path& file, int line) {
  return file.string() + ":" + std::to_string(line);
}

}  // namespace relight
