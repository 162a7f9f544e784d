// The linear octree of Sun 2005 §3.3.5: locational codes against hand-computed
// values (sentinel bit, ZYX octant order, parent = key >> 3, clamping outside the root), the
// insertion level L = ⌊log₂(s/r) − 1⌋ clamped to 0..10, at most 8 nodes per sample, and the
// query against brute force: every sample whose sphere contains a point is visited, once.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sources/emitters/linear_octree.h"

namespace relight {
namespace {

const LinearOctree kUnitRoot({0, 0, 0}, 1.0);

TEST(LinearOctreeKey, RootIsTheSentinelBitAlone) {
  EXPECT_EQ(kUnitRoot.key({0.1, 0.9, 0.5}, 0), 1u);
  EXPECT_EQ(kUnitRoot.key({0.9, 0.1, 0.2}, 0), 1u);
}

TEST(LinearOctreeKey, LevelOneOctantsInZyxOrder) {
  EXPECT_EQ(kUnitRoot.key({0.75, 0.75, 0.75}, 1), 0b1111u);  // (+x, +y, +z)
  EXPECT_EQ(kUnitRoot.key({0.25, 0.25, 0.25}, 1), 0b1000u);
  EXPECT_EQ(kUnitRoot.key({0.75, 0.25, 0.25}, 1), 0b1001u);  // x is the lowest bit
  EXPECT_EQ(kUnitRoot.key({0.25, 0.75, 0.25}, 1), 0b1010u);
  EXPECT_EQ(kUnitRoot.key({0.25, 0.25, 0.75}, 1), 0b1100u);  // z the highest
}

TEST(LinearOctreeKey, LevelTwoAppendsTheSubOctant) {
  // Cells at level 2 (quarters): x 3 = 0b11, y 0 = 0b00, z 2 = 0b10; the level-1 group is
  // the high bits (z y x) = 101, the level-2 group the low bits 001.
  EXPECT_EQ(kUnitRoot.key({0.875, 0.125, 0.625}, 2), 0b1101001u);
}

TEST(LinearOctreeKey, RootMadeFromPointsIsEnlargedAndCubic) {
  const std::vector<Vec3> points{{-1, 0, 0}, {1, 4, 0.5}};
  const LinearOctree octree(points);
  EXPECT_NEAR(octree.side(), 4 * (1 + 1e-3), 1e-12);
  const Vec3 c = octree.min_corner() + Vec3{1, 1, 1} * (0.5 * octree.side());
  EXPECT_NEAR(c.x, 0, 1e-12);
  EXPECT_NEAR(c.y, 2, 1e-12);
  EXPECT_NEAR(c.z, 0.25, 1e-12);
  // The box's extreme corners fall in opposite octants: (−x, −y, −z) and (+x, +y, +z).
  EXPECT_EQ(octree.key({-1, 0, 0}, 1), 0b1000u);
  EXPECT_EQ(octree.key({1, 4, 0.5}, 1), 0b1111u);
}

TEST(LinearOctreeKey, ParentIsTheKeyShiftedRightByThree) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    EXPECT_EQ(kUnitRoot.key(p, kOctreeMaxLevel) >> 30, 1u);  // 31 bits at the deepest level
    for (int level = 1; level <= kOctreeMaxLevel; ++level) {
      EXPECT_EQ(kUnitRoot.key(p, level) >> 3, kUnitRoot.key(p, level - 1)) << level;
    }
  }
}

TEST(LinearOctreeKey, PointsOutsideTheRootAreClampedToIt) {
  // (−5, 2, 0.6) clamps to (0, 1, 0.6): the far face y = 1 belongs to the upper node.
  EXPECT_EQ(kUnitRoot.key({-5, 2, 0.6}, 1), 0b1110u);
  EXPECT_EQ(kUnitRoot.key({1, 1, 1}, kOctreeMaxLevel), kUnitRoot.key({7, 8, 9}, kOctreeMaxLevel));
  EXPECT_EQ(kUnitRoot.key({1, 1, 1}, kOctreeMaxLevel), (1u << 31) - 1);  // all ones
}

TEST(LinearOctreeLevel, FloorOfLogTwoOfSideOverRadiusMinusOne) {
  EXPECT_EQ(octree_level_for_radius(8, 1), 2);  // s/r = 8: node side 2 = 2r
  EXPECT_EQ(octree_level_for_radius(8, 0.99), 2);
  EXPECT_EQ(octree_level_for_radius(8, 1.01), 1);
  EXPECT_EQ(octree_level_for_radius(8, 4), 0);  // r >= s/2: the root
  EXPECT_EQ(octree_level_for_radius(8, 100), 0);
  EXPECT_EQ(octree_level_for_radius(8, 1e-9), kOctreeMaxLevel);  // tiny r: the deepest
  EXPECT_EQ(octree_level_for_radius(8, 0), kOctreeMaxLevel);
  EXPECT_EQ(kUnitRoot.level_for_radius(1.0 / 16), 3);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> log_r(-12, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const double r = std::exp2(log_r(rng));
    const double formula = std::floor(std::log2(3.0 / r) - 1);
    const int expected = static_cast<int>(std::clamp(formula, 0.0, double(kOctreeMaxLevel)));
    EXPECT_EQ(octree_level_for_radius(3.0, r), expected) << r;
  }
}

TEST(LinearOctreeInsert, ASampleLivesInAtMostEightNodes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1), log_r(-12, 0);
  for (int trial = 0; trial < 300; ++trial) {
    LinearOctree octree({0, 0, 0}, 1.0);
    octree.insert(0, {u(rng), u(rng), u(rng)}, std::exp2(log_r(rng)));
    EXPECT_GE(octree.node_count(), 1u);
    EXPECT_LE(octree.node_count(), 8u);
  }
}

TEST(LinearOctreeQuery, VisitsEverySampleWhoseSphereContainsThePointOnce) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.2, 1.2), log_r(-9, -0.5);
  LinearOctree octree({0, 0, 0}, 1.0);
  struct Sphere {
    Vec3 c;
    double r;
  };
  std::vector<Sphere> spheres;
  for (std::uint32_t i = 0; i < 600; ++i) {
    // Radii from 2⁻⁹ to 0.7: every level 0..8 is used; some centres lie outside the root.
    spheres.push_back({{u(rng), u(rng), u(rng)}, std::exp2(log_r(rng))});
    octree.insert(i, spheres.back().c, spheres.back().r);
  }
  std::size_t contained = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Half the points near a sample's surface (inside or just outside), half anywhere.
    Vec3 p{u(rng), u(rng), u(rng)};
    if (trial % 2 == 0) {
      const Sphere& s = spheres[static_cast<std::size_t>(trial) % spheres.size()];
      const Vec3 dir = normalize(Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
      p = s.c + dir * (s.r * (0.999 + 0.002 * u(rng)));
    }
    std::multiset<std::uint32_t> visited;
    octree.for_each_candidate(p, [&](std::uint32_t id) { visited.insert(id); });
    for (std::uint32_t i = 0; i < spheres.size(); ++i) {
      const Vec3 d = p - spheres[i].c;
      EXPECT_LE(visited.count(i), 1u) << "sample " << i << " visited twice";
      if (dot(d, d) <= spheres[i].r * spheres[i].r) {
        ++contained;
        EXPECT_EQ(visited.count(i), 1u) << "trial " << trial << " misses sample " << i;
      }
    }
  }
  EXPECT_GT(contained, 3000u);  // the comparison is not vacuous
}

}  // namespace
}  // namespace relight
