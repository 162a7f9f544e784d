// Self-visibility cuts (sources/cuts/self_visibility.h) against a closed form: a point on a
// floor at distance d from a wall of height h (both far wider than d) sees the cosine-weighted
// sky but for the wall's configuration factor F = (1 − d / √(d² + h²)) / 2, so Σ over the cut
// of value · leaves · 4π/N = π (1 − F); and on an open floor π exactly, in one node per
// uniform region.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "math/direction_tree.h"
#include "sources/cuts/self_visibility.h"
#include "trace/ray_tracer.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(32768));
  return t;
}

// ∫ V cos dω from a cut: each node's value over its leaves' solid angle.
double integral(const DirectionCut& cut) {
  double sum = 0;
  for (std::size_t c = 0; c < cut.nodes.size(); ++c) {
    sum += cut.values[c] * static_cast<double>(std::size_t{1} << tree().height(cut.nodes[c]));
  }
  return sum * 4 * kPi / static_cast<double>(tree().leaf_count());
}

TEST(SelfVisibility, APointBesideAWallSeesTheSkyLessTheWallsConfigurationFactor) {
  const double d = 0.5, h = 1.0;
  // The wall x = d, 200 m wide along z, from the floor up to h.
  const std::vector<Vec3> p{{d, 0, -100}, {d, h, -100}, {d, h, 100}, {d, 0, 100}};
  const RayTracer wall(p, {{0, 1, 2}, {0, 2, 3}}, {0, 1});
  std::uint64_t rays = 0;
  const DirectionCut cut = self_visibility_cut(wall, tree(), {0, 0, 0}, {0, 1, 0}, 0.01, rays);
  const double f = 0.5 * (1 - d / std::sqrt(d * d + h * h));
  std::printf("beside a wall: %zu cut nodes, %.4f against pi (1 - F) = %.4f; %llu rays\n",
              cut.nodes.size(), integral(cut), kPi * (1 - f),
              static_cast<unsigned long long>(rays));
  EXPECT_NEAR(integral(cut), kPi * (1 - f), 0.01 * kPi * (1 - f));
  EXPECT_LT(rays, tree().leaf_count() * 6 / 10);  // only the upper hemisphere is traced

  const RayTracer nothing({}, {}, {});
  const DirectionCut open = self_visibility_cut(nothing, tree(), {0, 0, 0}, {0, 1, 0}, 0.01, rays);
  EXPECT_NEAR(integral(open), kPi, 0.005 * kPi);
}

}  // namespace
}  // namespace relight
