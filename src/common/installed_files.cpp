#include "common/installed_files.h"

#include <system_error>

namespace relight {

std::filesystem::path running_program() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return exe;
}

std::filesystem::path installed_share_folder(std::string_view name) {
  const std::filesystem::path exe = running_program();
  if (exe.empty()) return {};
  return exe.parent_path().parent_path() / "share" / "relight" / name;
}

}  // namespace relight
