// For fuzz targets whose reader takes a file (the mesh importers): the input written to a file
// with the given extension in this process's own temporary folder, replaced on every call and
// removed with the folder when the process exits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/temp_dir.h"

namespace relight::fuzz {

inline std::filesystem::path write_input(const std::uint8_t* data, std::size_t size,
                                         const std::string& extension) {
  static const testing::TempDir folder;  // removed when the process exits normally
  const auto file = folder.path() / ("input" + extension);
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace relight::fuzz
