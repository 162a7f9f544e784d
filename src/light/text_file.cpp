// Whole-file reads for the photometric parsers (see text_file.h).
#include "light/text_file.h"

#include <fstream>
#include <sstream>
#include <system_error>

#include "common/input_error.h"

namespace relight {

std::string read_text_file(const std::filesystem::path& file) {
  constexpr std::uintmax_t kMaxBytes = 64u << 20;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    fail_input(file.string(), "cannot read file: it does not exist or is not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) fail_input(file.string(), "cannot read file: " + ec.message());
  if (size > kMaxBytes) fail_input(file.string(), "file too large for photometric data");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_input(file.string(), "cannot open file");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) fail_input(file.string(), "cannot read file");
  return std::move(content).str();
}

}  // namespace relight
