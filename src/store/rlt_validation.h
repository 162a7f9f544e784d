// Every check a .rlt file passes before a single section is handed out: magic, format
// version, byte order, header and table checksums, file size, section bounds and
// alignment, zero padding, and every payload checksum: a truncated or corrupted file is
// rejected, never read as garbage.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "store/rlt_section_info.h"

namespace relight {

// The section table of the file whose bytes are given, in file order. Throws
// InputError "FILE: reason" (docs/rlt-format.md lists the reasons).
std::vector<RltSectionInfo> validate_rlt(const std::filesystem::path& file,
                                         std::span<const std::byte> bytes);

}  // namespace relight
