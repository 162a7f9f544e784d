#include "sources/cuts/cuts_precompute.h"

#include <atomic>
#include <chrono>

#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "sources/cuts/self_visibility.h"

namespace relight {

CutsTransfer precompute_cuts(const CutsSettings& settings, const Receivers& receivers,
                             std::span<const Vec3> ray_points, const TracedScene& traced,
                             bool progress) {
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
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace relight
