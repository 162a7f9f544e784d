#include "sources/nearfield/nearfield_precompute.h"

#include <chrono>
#include <cmath>

#include "math/sh.h"
#include "sources/nearfield/nearfield_transfer.h"

namespace relight {

NearfieldPrecompute::NearfieldPrecompute(const Scene& scene, std::uint64_t seed)
    : scene_(&scene), seed_(seed) {}

void NearfieldPrecompute::register_columns(ColumnRegistry& registry) {
  bounced_ = !scene_->emitters.empty() && scene_->precompute.nearfield_interreflection;
  if (bounced_) {
    columns_ = registry.add("near-field emitters", sh_count(scene_->precompute.nearfield_sh_order));
  }
}

PhaseTiming NearfieldPrecompute::compute_direct(const SourceContext& context,
                                                DirectColumns& columns) {
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
                                       context.receivers.normals, settings);
  if (bounced_) {
    // The transfer is receiver-major (K per receiver); the columns are basis-major.
    const Eigen::Index n = static_cast<Eigen::Index>(context.receivers.size());
    const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> t(
        result.transfer.data(), n, columns_.count);
    columns.of(columns_) = t;
  }
  const std::uint64_t rays = context.receivers.size() *
                             static_cast<std::uint64_t>(scene_->precompute.nearfield_directions);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  return {"near-field transfer", seconds.count(), rays};
}

void NearfieldPrecompute::take_indirect(const BounceResult& bounce) {
  if (!bounced_) return;
  const Eigen::Index n = bounce.indirect[0].rows();
  const auto k = static_cast<std::size_t>(columns_.count);
  result.interreflected.resize(static_cast<std::size_t>(n) * k * 3);
  for (int ch = 0; ch < 3; ++ch) {
    const auto columns = indirect_of(bounce, ch, columns_);
    for (Eigen::Index r = 0; r < n; ++r) {
      for (std::size_t c = 0; c < k; ++c) {
        result.interreflected[(static_cast<std::size_t>(r) * k + c) * 3 +
                              static_cast<std::size_t>(ch)] =
            columns(r, static_cast<Eigen::Index>(c));
      }
    }
  }
}

}  // namespace relight
