// What the run time reads of one portal's stored transfer (docs/rlt-format.md, the
// per-portal sections): its geometry for the shell, the direct cubemap record of each
// receiver (sources/portals/cubemap_encoding.h) and the indirect response to each SH basis
// radiance of its shell (blocked RGB × K, K = portal_sh_order², engine/transfer_blocks.h).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "engine/transfer_blocks.h"
#include "math/vec3.h"

namespace relight {

struct PortalTransferView {
  std::string name;
  int face_size = 32;
  Vec3 centre, outward;
  double diameter = 0;
  std::span<const std::uint8_t> records;
  std::span<const std::uint64_t> offsets;  // receivers + 1
  BlockedTransfer indirect;
};

}  // namespace relight
