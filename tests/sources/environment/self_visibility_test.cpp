// Self-visibility cuts (sources/environment/self_visibility.h) against a closed form: a point on a
// floor at distance d from a wall of height h (both far wider than d) sees the cosine-weighted
// sky but for the wall's configuration factor F = (1 − d / √(d² + h²)) / 2, so Σ over the
// cut's visible nodes of their leaves' n · ω · 4π/N = π (1 − F); and on an open floor π; the
// cut binary and its nodes merged only where their leaves agree.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "math/direction_tree.h"
#include "sources/environment/self_visibility.h"
#include "trace/ray_tracer.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(32768));
  return t;
}

// ∫ V cos dω from a cut at a point of normal n: the cosines of the leaves of its visible
// nodes, each leaf 4π/N; every value is 0 or 1.
double integral(const DirectionCut& cut, Vec3 n) {
  const std::size_t leaves = tree().leaf_count();
  double sum = 0;
  for (std::size_t c = 0; c < cut.nodes.size(); ++c) {
    EXPECT_TRUE(cut.values[c] == 0 || cut.values[c] == 1) << cut.values[c];
    if (cut.values[c] == 0) continue;
    const int h = tree().height(cut.nodes[c]);
    const std::size_t first = (std::size_t{cut.nodes[c]} << h) - leaves;
    for (std::size_t i = first; i < first + (std::size_t{1} << h); ++i) {
      sum += dot(n, tree().leaves[i]);
    }
  }
  return sum * 4 * kPi / static_cast<double>(leaves);
}

TEST(SelfVisibility, APointBesideAWallSeesTheSkyLessTheWallsConfigurationFactor) {
  const double d = 0.5, h = 1.0;
  // The wall x = d, 200 m wide along z, from the floor up to h.
  const std::vector<Vec3> p{{d, 0, -100}, {d, h, -100}, {d, h, 100}, {d, 0, 100}};
  const RayTracer wall(p, {{0, 1, 2}, {0, 2, 3}}, {0, 1});
  std::uint64_t rays = 0;
  const DirectionCut cut = self_visibility_cut(wall, tree(), {0, 0, 0}, {0, 1, 0}, 0, rays);
  const double f = 0.5 * (1 - d / std::sqrt(d * d + h * h));
  std::printf("beside a wall: %zu cut nodes, %.4f against pi (1 - F) = %.4f; %llu rays\n",
              cut.nodes.size(), integral(cut, {0, 1, 0}), kPi * (1 - f),
              static_cast<unsigned long long>(rays));
  EXPECT_NEAR(integral(cut, {0, 1, 0}), kPi * (1 - f), 0.01 * kPi * (1 - f));
  EXPECT_LT(rays, tree().leaf_count() * 6 / 10);  // only the upper hemisphere is traced

  const RayTracer nothing({}, {}, {});
  const DirectionCut open = self_visibility_cut(nothing, tree(), {0, 0, 0}, {0, 1, 0}, 0, rays);
  EXPECT_NEAR(integral(open, {0, 1, 0}), kPi, 0.005 * kPi);
  // The horizon is the open floor's one edge: a band of leaf-sized nodes along it.
  EXPECT_LT(open.nodes.size(), 2000u);
  std::printf("open floor: %zu cut nodes\n", open.nodes.size());
}

}  // namespace
}  // namespace relight
