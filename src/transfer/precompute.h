// `relight precompute`: everything a static scene needs so that every later change of
// luminaire distribution, aim, colour and dimming is a weighted sum (ARCHITECTURE §1):
// per luminaire the exact-direct geometry and the interreflected response to each SH
// basis intensity distribution Y_lm (world frame, l < sh_order), all luminaires' bases
// bounced together through one gather operator (rays traced once, ARCHITECTURE §4.3).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "transfer/luminaire_direct.h"
#include "transfer/receivers.h"

namespace relight {

struct PrecomputeOptions {
  bool progress = true;
  std::uint64_t seed = 1;
  int opening_samples = 16;  // points on a luminous opening for fractional visibility
};

struct LuminaireTransfer {
  DirectGeometry direct;
  std::vector<float> indirect_blocks;   // RGB, sh_order² bases, blocked (transfer_blocks.h)
  std::vector<float> direct_sh_blocks;  // 1 channel, same bases; only in "direct": "sh" mode
};

struct PhaseTiming {
  std::string name;
  double seconds = 0;
  std::uint64_t rays = 0;
};

struct Precomputed {
  PreparedMesh mesh;
  std::vector<std::uint32_t> triangle_is_portal;  // 1 for window glass, per mesh triangle
  Receivers receivers;
  int sh_order = 8;
  std::string direct_mode = "exact";
  int bounces = 0;
  std::vector<LuminaireTransfer> luminaires;  // in scene order
  std::vector<PhaseTiming> phases;
};

Precomputed precompute_transfer(const Scene& scene, const PrecomputeOptions& options);

}  // namespace relight
