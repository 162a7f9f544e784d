#include "sources/emitters/nearfield_precompute.h"

#include <chrono>
#include <cmath>

#include "sources/emitters/nearfield_transfer.h"

namespace relight {

NearfieldPrecompute::NearfieldPrecompute(const Scene& scene, std::uint64_t seed)
    : scene_(&scene), seed_(seed) {}

// The emitters' light bounces at run time, from where the emitters are then.
void NearfieldPrecompute::register_columns(ColumnRegistry&) {}

PhaseTiming NearfieldPrecompute::compute_direct(const SourceContext& context, DirectColumns&) {
  if (scene_->emitters.empty()) return {};
  const auto start = std::chrono::steady_clock::now();
  NearfieldTransferSettings settings;
  settings.order = scene_->precompute.nearfield_sh_order;
  settings.sqrt_directions =
      static_cast<int>(std::lround(std::sqrt(scene_->precompute.nearfield_directions)));
  settings.seed = seed_;
  const Bounds b = scene_->bounds();
  settings.max_distance = scene_->precompute.nearfield_shadow_distance > 0
                              ? scene_->precompute.nearfield_shadow_distance
                              : 0.25 * length(b.max - b.min);
  result.sh_order = settings.order;
  result.transfer = nearfield_transfer(context.traced.opaque, context.ray_points,
                                       context.receivers.normals, settings, context.ranks);
  const std::uint64_t rays = context.receivers.size() *
                             static_cast<std::uint64_t>(scene_->precompute.nearfield_directions);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  return {"near-field transfer", seconds.count(), rays};
}

void NearfieldPrecompute::take_indirect(const BounceResult&) {}

}  // namespace relight
