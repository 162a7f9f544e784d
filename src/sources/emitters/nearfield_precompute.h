// The near-field emitters' precompute (Sun 2005 §3.2.1): per receiver the shadowed SH
// transfer t_k = ∫ V max(0, n·ω) Y_k dω (world frame, l < nearfield_sh_order). With
// "nearfield_interreflection" the precompute also keeps the gather operator (sources/precompute.h),
// and the run time bounces the emitters' direct field through it
// (sources/emitters/emitter_lighting.h): bouncing the SH columns instead would assume the same
// incident radiance at every surface — the distant-light assumption that near-field emitters break
// (a ceiling above a downward panel would get no interreflected light at all). Nothing is stored
// without emitters.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/source_precompute.h"
#include "scene/scene.h"

namespace relight {

struct NearfieldTransfer {
  int sh_order = 0;             // 0: the scene has no emitters
  std::vector<float> transfer;  // receivers × K, K = sh_order²
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
};

}  // namespace relight
