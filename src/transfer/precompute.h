// `relight precompute`: everything a static scene needs so that every later change of
// luminaire distribution, aim, colour and dimming, and of the exterior seen through each
// window, is a weighted sum (ARCHITECTURE §1): per luminaire the exact-direct geometry and
// the interreflected response to each SH basis intensity distribution Y_lm (world frame,
// l < sh_order); per portal the direct cubemap per receiver and the interreflected response
// to each SH basis radiance of its shell (l < portal_sh_order). All luminaires' and portals'
// bases bounce together through one gather operator (rays traced once, ARCHITECTURE §4.3).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "transfer/luminaire_direct.h"
#include "transfer/portal_direct.h"
#include "transfer/portal_geometry.h"
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

// A portal's transfer (the interior-scene paper §4.1): the direct cubemap per receiver and
// the interreflected response to each SH basis radiance Y_k (l < sh_order) of its shell.
struct PortalTransfer {
  PortalGeometry geometry;
  PortalDirect direct;                 // direct.sh_columns is emptied once bounced
  std::vector<float> indirect_blocks;  // RGB, sh_order² bases, blocked (transfer_blocks.h)
};

struct PhaseTiming {
  std::string name;
  double seconds = 0;
  std::uint64_t rays = 0;
};

inline constexpr std::uint32_t kGlassOutsidePortals = 0xFFFFFFFFu;

struct Precomputed {
  PreparedMesh mesh;
  // Per mesh triangle: 0 opaque, p + 1 for glass of portal p, kGlassOutsidePortals for glass
  // of a "portal": true material that no portal lists (an opening to darkness).
  std::vector<std::uint32_t> triangle_portal;
  Receivers receivers;
  int sh_order = 8;
  std::string direct_mode = "exact";
  int bounces = 0;
  std::vector<LuminaireTransfer> luminaires;  // in scene order
  int portal_sh_order = 6;
  std::vector<PortalTransfer> portals;  // in scene order
  // Near-field emitters (scene has emitters): per receiver nearfield_sh_order² shadowed transfer
  // coefficients (transfer/nearfield_transfer.h), and with interreflection the bounced part,
  // per receiver K × RGB. Empty otherwise.
  int nearfield_sh_order = 0;
  std::vector<float> nearfield_transfer;
  std::vector<float> nearfield_interreflected;
  std::vector<PhaseTiming> phases;
  std::vector<std::string> warnings;  // e.g. portals too large for their shells (§6)
};

Precomputed precompute_transfer(const Scene& scene, const PrecomputeOptions& options);

}  // namespace relight
