// For fuzz targets whose reader takes a file (the mesh importers): the input written to a file
// with the given extension in this process's own temporary folder, replaced on every call.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace relight::fuzz {

inline std::filesystem::path write_input(const std::uint8_t* data, std::size_t size,
                                         const std::string& extension) {
  static const std::filesystem::path folder = [] {
    const auto f = std::filesystem::temp_directory_path() /
                   ("relight-fuzz-" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(f);
    return f;
  }();
  const auto file = folder / ("input" + extension);
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace relight::fuzz
