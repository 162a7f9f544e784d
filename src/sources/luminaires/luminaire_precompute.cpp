#include "sources/luminaires/luminaire_precompute.h"

#include <chrono>

#include "engine/transfer_blocks.h"
#include "light/luminaire_frame.h"
#include "math/sh.h"
#include "sources/luminaires/sh_direct.h"

namespace relight {

LuminairePrecompute::LuminairePrecompute(const Scene& scene, int opening_samples)
    : scene_(&scene), opening_samples_(opening_samples) {}

void LuminairePrecompute::register_columns(ColumnRegistry& registry) {
  const int k = sh_count(scene_->precompute.sh_order);
  for (std::size_t j = 0; j < scene_->luminaires.size(); ++j) {
    columns_.push_back(registry.add("luminaire " + std::to_string(columns_.size()), k));
  }
}

PhaseTiming LuminairePrecompute::compute_direct(const SourceContext& context,
                                                DirectColumns& columns) {
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t rays = 0;
  const int order = scene_->precompute.sh_order;
  for (std::size_t j = 0; j < scene_->luminaires.size(); ++j) {
    const Luminaire& l = scene_->luminaires[j];
    const PlacedLuminaire placed = place_luminaire(l);
    const std::vector<Vec3> offsets = opening_sample_offsets(
        luminaire_opening(l, placed.distribution.opening()), placed.frame, opening_samples_);
    LuminaireTransfer t;
    t.direct = compute_direct_geometry(context.receivers, context.ray_points, context.traced.opaque,
                                       l.position, offsets, context.progress, context.ranks);
    rays += t.direct.rays;
    columns.set(columns_[j], sh_basis_direct(t.direct, order));
    if (scene_->precompute.direct == "sh") {
      t.direct_sh_blocks = pack_blocks({columns.of(columns_[j])});
    }
    transfers.push_back(std::move(t));
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  return {"direct visibility", seconds.count(), rays};
}

void LuminairePrecompute::take_indirect(const BounceResult& result) {
  for (std::size_t j = 0; j < transfers.size(); ++j) {
    transfers[j].indirect = pack_indirect_blocks(
        result, columns_[j], transfer_storage_named(scene_->precompute.storage));
  }
}

}  // namespace relight
