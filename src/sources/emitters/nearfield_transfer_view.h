// What the run time reads of the near-field emitters' stored transfer (docs/rlt-format.md,
// NFTR): the shadowed SH transfer per receiver. The receivers, the static occluders and the
// gather operator their lighting also needs are the scene's (engine/runtime_scene.h).
#pragma once

#include <span>

namespace relight {

struct NearfieldTransferView {
  int sh_order = 0;                 // 0: the scene has no emitters
  std::span<const float> transfer;  // receivers × K shadowed transfer, K = sh_order²
};

}  // namespace relight
