// Checked, atomic write of an encoded image (see image_bytes.h). C stdio is used rather
// than iostreams because it reports the failing errno (disk full, file too large, ...).
#include "image/image_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include "common/atomic_file.h"
#include "common/input_error.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

[[noreturn]] void fail_errno(const fs::path& target, const std::string& what) {
  fail_input(target.string(), what + ": " + std::strerror(errno));
}

void write_file(const fs::path& file, const fs::path& target, std::span<const std::uint8_t> bytes) {
  std::unique_ptr<std::FILE, FileCloser> out(std::fopen(file.c_str(), "wb"));
  if (!out) fail_errno(target, "cannot create file");
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), out.get()) != bytes.size()) {
    fail_errno(target, "cannot write");
  }
  if (std::fflush(out.get()) != 0) fail_errno(target, "cannot write");
  if (std::fclose(out.release()) != 0) fail_errno(target, "cannot close");
}

}  // namespace

void write_bytes_atomically(const fs::path& target, std::span<const std::uint8_t> bytes) {
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    fail_input(target.string(), "folder " + folder.string() + " does not exist");
  }
  try {
    write_atomically(target, [&](const fs::path& tmp) { write_file(tmp, target, bytes); });
  } catch (const fs::filesystem_error& e) {  // the final rename
    fail_input(target.string(), "cannot rename temporary into place: " + e.code().message());
  }
}

}  // namespace relight
