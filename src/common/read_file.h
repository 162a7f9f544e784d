// Whole-file reads for every parser (scene JSON, meshes, photometry), failing as
// InputError "FILE: reason" rather than with a stream error, with an optional size
// limit for formats whose files are never large.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

namespace relight {

// The file's bytes. InputError when it is missing, not a regular file, unreadable, or
// larger than max_bytes.
std::string read_file(const std::filesystem::path& file,
                      std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

}  // namespace relight
