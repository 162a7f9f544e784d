// A source's blocked SH transfer as a .rlt section (docs/rlt-format.md, "Stored transfer"):
// element f32, or f16 with the scale's exponent in the section's flags (the scale 2^(flags − 128),
// engine/transfer_blocks.h). Pinned by tests/engine/transfer_blocks_test.cpp.
#pragma once

#include <cstdint>
#include <string>

#include "engine/transfer_blocks.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// Adds `t` as section `type`; `t` must outlive the writer's write().
void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          const PackedTransfer& t);

// The section `type` as written by add_transfer_section. InputError "FILE: reason" when it is
// missing or of another element type.
BlockedTransfer transfer_section(const RltFile& file, std::uint32_t type);

}  // namespace relight
