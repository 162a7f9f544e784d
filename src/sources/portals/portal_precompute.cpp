#include "sources/portals/portal_precompute.h"

#include <chrono>

#include "math/sh.h"

namespace relight {

PortalPrecompute::PortalPrecompute(const Scene& scene, std::uint64_t seed)
    : scene_(&scene), seed_(seed) {}

void PortalPrecompute::register_columns(ColumnRegistry& registry) {
  const int k = sh_count(scene_->precompute.portal_sh_order);
  for (const Portal& p : scene_->portals) columns_.push_back(registry.add("portal " + p.name, k));
}

PhaseTiming PortalPrecompute::compute_direct(const SourceContext& context, DirectColumns& columns) {
  if (scene_->portals.empty()) return {};
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t rays = 0;
  std::vector<std::uint8_t> glass = portal_vertices(context.mesh, scene_->materials);
  glass.resize(context.receivers.size(), 0);  // sensors always receive
  PortalDirectSettings settings;
  settings.face_size = scene_->precompute.portal_face_size;
  settings.sh_order = scene_->precompute.portal_sh_order;
  settings.samples_per_cell = scene_->precompute.portal_samples_per_cell;
  std::vector<PortalGeometry> geometry = portal_geometry(*scene_, context.mesh);
  warnings = shell_size_warnings(*scene_, geometry);
  for (std::size_t p = 0; p < scene_->portals.size(); ++p) {
    PortalTransfer t;
    t.geometry = std::move(geometry[p]);
    settings.seed = seed_ + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(p + 1);
    t.direct = compute_portal_direct(context.receivers, context.ray_points, glass, context.mesh,
                                     context.traced, t.geometry, settings, context.progress,
                                     context.ranks);
    rays += t.direct.rays;
    columns.set(columns_[p], t.direct.sh_columns);
    t.direct.sh_columns.resize(0, 0);
    transfers.push_back(std::move(t));
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  return {"portal direct", seconds.count(), rays};
}

void PortalPrecompute::take_indirect(const BounceResult& result) {
  for (std::size_t p = 0; p < transfers.size(); ++p) {
    transfers[p].indirect = pack_indirect_blocks(
        result, columns_[p], transfer_storage_named(scene_->precompute.storage));
  }
}

}  // namespace relight
