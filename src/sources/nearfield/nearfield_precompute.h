// The near-field emitters' precompute (Sun 2005 §3.2.1): per receiver the shadowed SH
// transfer t_k = ∫ V max(0, n·ω) Y_k dω (world frame, l < nearfield_sh_order), and with
// "nearfield_interreflection" the same columns bounced through the shared gather operator.
// Nothing is stored for a scene without emitters.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/source_precompute.h"
#include "scene/scene.h"

namespace relight {

struct NearfieldTransfer {
  int sh_order = 0;                   // 0: the scene has no emitters
  std::vector<float> transfer;        // receivers × K, K = sh_order²
  std::vector<float> interreflected;  // receivers × K × RGB, when bounced
};

class NearfieldPrecompute : public SourcePrecompute {
 public:
  NearfieldPrecompute(const Scene& scene, std::uint64_t seed);
  void register_columns(ColumnRegistry& registry) override;
  PhaseTiming compute_direct(const SourceContext& context, DirectColumns& columns) override;
  void take_indirect(const BounceResult& result) override;

  NearfieldTransfer result;

 private:
  const Scene* scene_;
  std::uint64_t seed_;
  ColumnRange columns_;
  bool bounced_ = false;
};

}  // namespace relight
