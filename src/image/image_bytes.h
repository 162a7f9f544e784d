// Image encoders (EXR, PNG) encode into memory and hand the bytes to this one writer, so every
// format gets the same atomic write (common/atomic_file.h) and the same error messages: "PATH:
// reason", with the reason taken from errno.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace relight {

// Writes bytes to a temporary beside target, then renames it over target. Throws
// InputError "TARGET: reason" when the folder is missing or any write, flush, close or
// rename fails; the temporary is removed and an existing target is left untouched.
void write_bytes_atomically(const std::filesystem::path& target,
                            std::span<const std::uint8_t> bytes);

}  // namespace relight
