// The luminaires' precompute (Dobashi et al. 1995 §3, with exact direct light, docs/decisions.md
// "Direct light is geometry"): per luminaire the exact-direct geometry toward every receiver, and
// the response to each SH basis intensity distribution Y_k (world frame, l < sh_order) — its direct
// irradiance as K bounced columns, its interreflection taken back after the shared bounce solve.
#pragma once

#include <string>
#include <vector>

#include "engine/source_precompute.h"
#include "engine/transfer_blocks.h"
#include "scene/scene.h"
#include "sources/luminaires/luminaire_direct.h"

namespace relight {

struct LuminaireTransfer {
  DirectGeometry direct;
  PackedTransfer indirect;              // RGB, sh_order² bases, blocked (transfer_blocks.h)
  std::vector<float> direct_sh_blocks;  // 1 channel, same bases; only in "direct": "sh" mode
};

class LuminairePrecompute : public SourcePrecompute {
 public:
  // `opening_samples`: points on a luminous opening for fractional visibility.
  LuminairePrecompute(const Scene& scene, int opening_samples);
  void register_columns(ColumnRegistry& registry) override;
  PhaseTiming compute_direct(const SourceContext& context, DirectColumns& columns) override;
  void take_indirect(const BounceResult& result) override;

  std::vector<LuminaireTransfer> transfers;  // in scene order

 private:
  const Scene* scene_;
  int opening_samples_;
  std::vector<ColumnRange> columns_;
};

}  // namespace relight
