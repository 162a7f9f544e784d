// sources/emitters/receiver_bvh.h (Sun 2005 Algorithm 3.3): median splits along the longest axis
// give a balanced tree whose nodes hold contiguous receiver ranges, with the sample position (mean)
// and radius (half box diagonal) the oracle needs.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "sources/emitters/receiver_bvh.h"

namespace relight {
namespace {

std::vector<Vec3> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = {3 * u(rng), u(rng), 0.5 * u(rng)};
  return p;
}

TEST(ReceiverBvh, BalancedMedianSplitsWithMeansAndRadii) {
  const std::vector<Vec3> points = random_points(1000, 3);
  const ReceiverBvh bvh = build_receiver_bvh(points, 4);
  std::vector<std::uint32_t> sorted = bvh.order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  ASSERT_EQ(bvh.nodes[0].count, 1000u);
  // The root splits along x (the longest extent) at the median.
  const ReceiverBvhNode& root = bvh.nodes[0];
  const ReceiverBvhNode& left = bvh.nodes[static_cast<std::size_t>(root.left)];
  const ReceiverBvhNode& right = bvh.nodes[static_cast<std::size_t>(root.right)];
  EXPECT_EQ(left.count, 500u);
  EXPECT_LE(left.box_max.x, right.box_min.x);
  std::size_t leaves = 0;
  for (const ReceiverBvhNode& node : bvh.nodes) {
    Vec3 sum{0, 0, 0};
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      const Vec3 p = points[bvh.order[k]];
      for (int a = 0; a < 3; ++a) {
        EXPECT_GE(p[a], node.box_min[a]);
        EXPECT_LE(p[a], node.box_max[a]);
      }
      sum = sum + p;
    }
    const Vec3 mean = sum * (1.0 / node.count);
    EXPECT_NEAR(length(mean - node.sample_position), 0, 1e-12);
    EXPECT_NEAR(node.radius, 0.5 * length(node.box_max - node.box_min), 1e-12);
    if (node.leaf()) {
      ++leaves;
      EXPECT_LE(node.count, 4u);
      continue;
    }
    const ReceiverBvhNode& a = bvh.nodes[static_cast<std::size_t>(node.left)];
    const ReceiverBvhNode& b = bvh.nodes[static_cast<std::size_t>(node.right)];
    EXPECT_EQ(a.first, node.first);
    EXPECT_EQ(b.first, node.first + a.count);
    EXPECT_EQ(a.count + b.count, node.count);
    EXPECT_LE(b.count - a.count, 1u);  // balanced
  }
  EXPECT_EQ(bvh.nodes.size(), 2 * leaves - 1);  // a full binary tree
}

TEST(ReceiverBvh, EmptyAndSinglePoint) {
  EXPECT_TRUE(build_receiver_bvh({}).nodes.empty());
  const std::vector<Vec3> one{{1, 2, 3}};
  const ReceiverBvh bvh = build_receiver_bvh(one);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_TRUE(bvh.nodes[0].leaf());
  EXPECT_EQ(bvh.nodes[0].radius, 0);
  EXPECT_THROW(build_receiver_bvh(one, 0), std::invalid_argument);
}

}  // namespace
}  // namespace relight
