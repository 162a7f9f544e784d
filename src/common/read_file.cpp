#include "common/read_file.h"

#include <fstream>
#include <sstream>
#include <system_error>

#include "common/input_error.h"

namespace relight {

std::string read_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    fail_input(file.string(), "cannot open file: no such file");
  if (!std::filesystem::is_regular_file(file, ec)) {
    fail_input(file.string(), "cannot open file: not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) fail_input(file.string(), "cannot read file: " + ec.message());
  if (size > max_bytes) {
    fail_input(file.string(), "file too large (" + std::to_string(size) + " bytes, at most " +
                                  std::to_string(max_bytes) + " expected)");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_input(file.string(), "cannot open file");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) fail_input(file.string(), "cannot read file");
  return std::move(content).str();
}

}  // namespace relight
