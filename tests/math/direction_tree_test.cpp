// The cuts' direction set and tree (math/direction_tree.h): 32,768 directions as even as point
// repulsion makes them (every nearest neighbour within 20 % of the hexagonal spacing, caps of
// 256 expected directions within 10 % of it), and a complete tree whose nodes cover their
// leaves, halve the sphere level by level and bound them in a cone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "math/direction_tree.h"
#include "math/sampling.h"

namespace relight {
namespace {

constexpr std::size_t kCount = 32768;

TEST(DirectionTree, RepulsedDirectionsAreEvenlySpread) {
  const std::vector<Vec3> d = repulsed_directions(kCount);
  ASSERT_EQ(d.size(), kCount);
  const DirectionTree tree = build_direction_tree(d);
  // Nearest neighbours, through the tree's cones (a brute force over 32,768² pairs is slow).
  const double hexagonal = std::sqrt(8 * kPi / (std::sqrt(3.0) * kCount));
  double shortest = 1, longest = 0;
  for (std::size_t i = 0; i < kCount; i += 7) {
    const Vec3 p = tree.leaves[i];
    double best = 1e9;
    std::vector<std::size_t> stack{1};
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      // Skip a node whose cone lies farther from p than the best found so far.
      const double angle = std::acos(std::clamp(dot(p, tree.axis[k]), -1.0, 1.0)) -
                           std::acos(std::clamp(tree.cos_half_angle[k], -1.0, 1.0));
      if (angle > 2 * std::asin(std::min(1.0, best / 2))) continue;
      if (k >= kCount) {
        if (k - kCount != i) best = std::min(best, length(tree.leaves[k - kCount] - p));
        continue;
      }
      stack.push_back(2 * k);
      stack.push_back(2 * k + 1);
    }
    shortest = std::min(shortest, best);
    longest = std::max(longest, best);
  }
  std::printf("nearest neighbours %.4f to %.4f (hexagonal spacing %.4f)\n", shortest, longest,
              hexagonal);
  EXPECT_GT(shortest, 0.8 * hexagonal);
  EXPECT_LT(longest, 1.2 * hexagonal);
  // Caps of 256 expected directions about random axes.
  Pcg32 rng(3, 1);
  const double cap = 1 - 2 * 256.0 / kCount;  // cos of the cap holding 256/N of the sphere
  double worst = 0;
  for (int c = 0; c < 50; ++c) {
    const Vec3 axis = sample_uniform_sphere(rng.next_double(), rng.next_double());
    const auto in = std::count_if(d.begin(), d.end(), [&](Vec3 v) { return dot(v, axis) >= cap; });
    worst = std::max(worst, std::abs(static_cast<double>(in) / 256 - 1));
  }
  std::printf("caps of 256: worst %.1f %% off\n", 100 * worst);
  EXPECT_LT(worst, 0.1);
}

TEST(DirectionTree, NodesCoverTheirLeavesInConesThatHalveLevelByLevel) {
  const DirectionTree tree = build_direction_tree(repulsed_directions(kCount));
  ASSERT_EQ(tree.leaf_count(), kCount);
  EXPECT_EQ(tree.height(1), 15);
  EXPECT_EQ(tree.height(kCount), 0);
  EXPECT_EQ(tree.height(2 * kCount - 1), 0);
  for (std::size_t k = 1; k < kCount; ++k) {
    const int h = tree.height(k);
    const std::size_t first = (k << h) - kCount;
    for (std::size_t i = first; i < first + (std::size_t{1} << h); ++i) {
      ASSERT_GE(dot(tree.axis[k], tree.leaves[i]), tree.cos_half_angle[k] - 1e-12) << k;
    }
  }
  // Mean cone half-angle per level: each level's caps hold half the directions of the one
  // above, so their solid angle halves: the half-angle shrinks by about √2 (down to caps of 4
  // directions; a pair's cone is half their spacing).
  std::vector<double> mean(16, 0);
  for (std::size_t k = 1; k < kCount; ++k) {
    const int depth = 15 - tree.height(k);
    mean[static_cast<std::size_t>(depth)] +=
        std::acos(tree.cos_half_angle[k]) / static_cast<double>(std::size_t{1} << depth);
  }
  for (int depth = 6; depth < 13; ++depth) {
    const double ratio =
        mean[static_cast<std::size_t>(depth)] / mean[static_cast<std::size_t>(depth + 1)];
    EXPECT_NEAR(ratio, std::sqrt(2.0), 0.25) << "depth " << depth;
  }
  std::printf("cone half-angles: depth 1 %.1f°, 8 %.2f°, 14 %.3f°\n", mean[1] * 180 / kPi,
              mean[8] * 180 / kPi, mean[14] * 180 / kPi);
  EXPECT_THROW(build_direction_tree(std::vector<Vec3>(100, Vec3{0, 1, 0})), std::invalid_argument);
}

}  // namespace
}  // namespace relight
