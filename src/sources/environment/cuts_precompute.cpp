#include "sources/environment/cuts_precompute.h"

#include <atomic>
#include <chrono>

#include <tbb/blocked_range.h>

#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "sources/environment/self_visibility.h"

namespace relight {

namespace {

// Appends to `store` the self-visibility cut of every point (rays from `ray_points`, pushed
// off the surface along `normals`) against `occluders`; returns the rays traced.
std::uint64_t append_self_visibility(HeightCuts& store, const Occluders& occluders,
                                     const DirectionTree& tree, std::span<const Vec3> ray_points,
                                     std::span<const Vec3> normals, double threshold,
                                     Progress* bar) {
  std::vector<DirectionCut> cuts(ray_points.size());
  std::atomic<std::uint64_t> rays{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cuts.size(), 16), [&](const auto& range) {
    std::uint64_t here = 0;
    for (std::size_t r = range.begin(); r < range.end(); ++r) {
      const Vec3 n = normals[r];
      cuts[r] = self_visibility_cut(occluders, tree, offset_from_surface(ray_points[r], n), n,
                                    threshold, here);
    }
    rays += here;
    if (bar != nullptr) bar->advance(range.size());
  });
  for (DirectionCut& cut : cuts) {
    append_cut(store, cut);
    cut = {};
  }
  return rays;
}

}  // namespace

CutsTransfer precompute_cuts(const CutsSettings& settings, const Receivers& receivers,
                             std::span<const Vec3> ray_points, const TracedScene& traced,
                             std::span<const ObjectMesh> objects, bool progress) {
  const auto start = std::chrono::steady_clock::now();
  CutsTransfer out;
  const DirectionTree tree =
      build_direction_tree(repulsed_directions(static_cast<std::size_t>(settings.directions)));
  out.directions = tree.leaves;
  out.threshold = settings.threshold;
  out.self_visibility = make_height_cuts(tree);

  Progress bar("self-visibility cuts", receivers.size(), progress);
  out.rays = append_self_visibility(out.self_visibility, Occluders(traced.opaque, &traced.portals),
                                    tree, ray_points, receivers.normals, settings.threshold, &bar);
  bar.finish();
  // The objects: each one's field, and its vertices' cuts of itself.
  out.object_self_visibility = make_height_cuts(tree);
  out.field_cuts = make_height_cuts(tree);
  out.field_first.push_back(0);
  for (const ObjectMesh& object : objects) {
    const VisibilityField field =
        precompute_visibility_field(object, tree, settings, out.field_cuts);
    out.fields.push_back(field.layout);
    out.field_first.push_back(out.field_cuts.view().cut_count());
    out.rays += field.rays;
    const RayTracer own(object.positions, object.triangles,
                        sequential_ids(object.triangles.size()));
    out.rays += append_self_visibility(out.object_self_visibility, own, tree, object.ray_points,
                                       object.normals, settings.threshold, nullptr);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace relight
