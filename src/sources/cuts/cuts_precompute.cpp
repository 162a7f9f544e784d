#include "sources/cuts/cuts_precompute.h"

#include <atomic>
#include <chrono>

#include <tbb/blocked_range.h>

#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "sources/cuts/self_visibility.h"

namespace relight {

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

  const Occluders occluders(traced.opaque, &traced.portals);
  const std::size_t count = receivers.size();
  std::vector<DirectionCut> cuts(count);
  std::atomic<std::uint64_t> rays{0};
  Progress bar("self-visibility cuts", count, progress);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16), [&](const auto& range) {
    std::uint64_t traced_here = 0;
    for (std::size_t r = range.begin(); r < range.end(); ++r) {
      const Vec3 n = receivers.normals[r];
      cuts[r] = self_visibility_cut(occluders, tree, offset_from_surface(ray_points[r], n), n,
                                    settings.threshold, traced_here);
    }
    rays += traced_here;
    bar.advance(range.size());
  });
  bar.finish();
  for (DirectionCut& cut : cuts) {
    append_cut(out.self_visibility, cut);
    cut = {};
  }
  out.rays = rays;
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
    std::vector<DirectionCut> self(object.positions.size());
    std::atomic<std::uint64_t> object_rays{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, self.size(), 16), [&](const auto& range) {
      std::uint64_t here = 0;
      for (std::size_t v = range.begin(); v < range.end(); ++v) {
        const Vec3 n = object.normals[v];
        self[v] = self_visibility_cut(own, tree, offset_from_surface(object.ray_points[v], n), n,
                                      settings.threshold, here);
      }
      object_rays += here;
    });
    for (const DirectionCut& cut : self) append_cut(out.object_self_visibility, cut);
    out.rays += object_rays;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace relight
