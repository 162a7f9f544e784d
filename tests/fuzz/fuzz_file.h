// For fuzz targets whose reader takes a file (the mesh importers): the input written to a file
// with the given extension in this process's own temporary folder, replaced on every call and
// removed with the folder when the process exits.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace relight::fuzz {

// This process's folder, removed when the process exits normally.
class InputFolder {
 public:
  InputFolder()
      : path_(std::filesystem::temp_directory_path() /
              ("relight-fuzz-" + std::to_string(static_cast<long>(getpid())))) {
    std::filesystem::create_directories(path_);
  }
  ~InputFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  InputFolder(const InputFolder&) = delete;
  InputFolder& operator=(const InputFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::filesystem::path write_input(const std::uint8_t* data, std::size_t size,
                                         const std::string& extension) {
  static const InputFolder folder;
  const auto file = folder.path() / ("input" + extension);
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace relight::fuzz
