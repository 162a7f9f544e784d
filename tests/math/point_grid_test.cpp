// The point grid (math/point_grid.h): its nearest point equals a search of every point, for
// directions on the sphere near and far from the points and for a grid whose cells are
// smaller than the points' spacing (where the fallback over every point decides).
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "math/direction_tree.h"
#include "math/point_grid.h"

namespace relight {
namespace {

std::uint32_t brute_nearest(const std::vector<Vec3>& points, Vec3 p) {
  std::uint32_t best = 0;
  for (std::uint32_t i = 1; i < points.size(); ++i) {
    if (length(points[i] - p) < length(points[best] - p)) best = i;
  }
  return best;
}

TEST(PointGrid, TheNearestPointIsTheOneASearchOfEveryPointFinds) {
  const std::vector<Vec3> points = repulsed_directions(1024, 5);
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (const double cell : {0.25, 0.01}) {
    const PointGrid grid(points, cell);
    for (int k = 0; k < 2000; ++k) {
      const Vec3 d = normalize(Vec3{g(rng), g(rng), g(rng)});
      const std::uint32_t found = grid.nearest(d);
      ASSERT_NEAR(length(points[found] - d), length(points[brute_nearest(points, d)] - d), 1e-12)
          << "cell " << cell << " direction " << k;
    }
  }
}

TEST(PointGrid, NeighboursWithinACellAreAllVisited) {
  const std::vector<Vec3> points = repulsed_directions(256, 0);
  const PointGrid grid(points, 0.3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<bool> seen(points.size(), false);
    grid.near(points[i], [&](std::uint32_t j) { seen[j] = true; });
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (length(points[j] - points[i]) <= 0.3) {
        ASSERT_TRUE(seen[j]) << i << " " << j;
      }
    }
  }
}

}  // namespace
}  // namespace relight
