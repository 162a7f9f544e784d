// What the run time reads of one luminaire's stored transfer (docs/rlt-format.md, the
// per-luminaire sections): spans into the memory-mapped .rlt, or into a precompute still in
// memory. Layouts: engine/transfer_blocks.h.
#pragma once

#include <span>

#include "engine/transfer_blocks.h"

namespace relight {

struct LuminaireTransferView {
  std::span<const float> dir_x, dir_y, dir_z, factor;  // direct geometry, per receiver
  BlockedTransfer indirect;                            // blocked RGB × K
  std::span<const float> direct_sh;                    // blocked 1 × K ("sh" mode only)
};

}  // namespace relight
