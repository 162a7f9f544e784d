// Whole-file reads for the photometric parsers, failing as InputError ("FILE: reason")
// rather than with a stream error, and refusing files too large to be photometry.
#pragma once

#include <filesystem>
#include <string>

namespace relight {

// The file's bytes; InputError when it cannot be opened or read, or exceeds 64 MiB.
std::string read_text_file(const std::filesystem::path& file);

}  // namespace relight
