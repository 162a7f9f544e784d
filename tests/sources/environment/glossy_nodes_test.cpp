// The direction tree split to a glossy view's node size (sources/environment/glossy_nodes.h): the
// nodes where the split stops cover the sphere's leaves once, in leaf order, each a leaf or
// within the size and its parent not; every node at or above them owns exactly the range the
// split of that node alone visits (as EnvironmentLighting split a cut's node before), and
// every node below them names the one holding it; the lights' planes hold the moments and
// directions of the stopping nodes in that order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "math/direction_tree.h"
#include "sources/environment/glossy_nodes.h"

namespace relight {
namespace {

// The split of node k on its own, lower child first.
void split(const DirectionTree& tree, double cos_limit, std::uint32_t k,
           std::vector<std::uint32_t>& out) {
  if (k < tree.leaf_count() && tree.cos_half_angle[k] < cos_limit) {
    split(tree, cos_limit, 2 * k, out);
    split(tree, cos_limit, 2 * k + 1, out);
    return;
  }
  out.push_back(k);
}

TEST(GlossyNodes,
     StopNodesCoverTheLeavesOnceNodesAboveOwnTheirSplitsRangeAndNodesBelowTheirHolder) {
  const DirectionTree tree = build_direction_tree(repulsed_directions(4096, 5));
  const double cos_limit = std::cos(6 * kPi / 180);
  const GlossyNodes g = glossy_nodes(tree, cos_limit);
  const std::size_t n = tree.leaf_count();
  ASSERT_GT(g.node.size(), 100u);
  ASSERT_LT(g.node.size(), n);  // some stop above the leaves
  // In leaf order, covering every leaf once.
  std::uint64_t next_leaf = 0;
  for (const std::uint32_t k : g.node) {
    const int h = tree.height(k);
    EXPECT_EQ((std::uint64_t{k} << h) - n, next_leaf);
    next_leaf += std::uint64_t{1} << h;
    EXPECT_TRUE(k >= n || tree.cos_half_angle[k] >= cos_limit);
    EXPECT_LT(tree.cos_half_angle[k / 2], cos_limit);  // the parent was split
  }
  EXPECT_EQ(next_leaf, n);
  int above = 0, below = 0;
  for (std::uint32_t k = 1; k < 2 * n; ++k) {
    if (g.within[k] != GlossyNodes::kNone) {
      ++below;
      EXPECT_EQ(g.first[k], GlossyNodes::kNone);
      EXPECT_EQ(g.last[k], GlossyNodes::kNone);
      std::uint32_t a = k / 2;  // the first ancestor not below is the split node holding k
      while (a >= 1 && g.within[a] != GlossyNodes::kNone) a /= 2;
      ASSERT_GE(a, 1u) << "node " << k;
      EXPECT_EQ(g.last[a] - g.first[a], 1u);
      EXPECT_EQ(g.node[g.first[a]], a);
      EXPECT_EQ(g.within[k], g.first[a]);
      continue;
    }
    ++above;
    std::vector<std::uint32_t> own;
    split(tree, cos_limit, k, own);
    ASSERT_EQ(own.size(), g.last[k] - g.first[k]) << "node " << k;
    for (std::size_t i = 0; i < own.size(); ++i) EXPECT_EQ(g.node[g.first[k] + i], own[i]);
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(below, 0);
}

TEST(GlossyNodes, LightsHoldTheStopNodesMomentsAndDirectionsInTheirOrder) {
  const DirectionTree tree = build_direction_tree(repulsed_directions(1024, 5));
  const GlossyNodes g = glossy_nodes(tree, std::cos(10 * kPi / 180));
  std::vector<RgbMoment> moments(2 * tree.leaf_count());
  std::vector<Vec3> directions(2 * tree.leaf_count());
  for (std::size_t k = 1; k < moments.size(); ++k) {
    for (int i = 0; i < 3; ++i) {
      moments[k].r[i] = static_cast<float>(k) + 0.1f * static_cast<float>(i);
      moments[k].g[i] = -static_cast<float>(k);
      moments[k].b[i] = 0.5f * static_cast<float>(i);
    }
    directions[k] = tree.axis[k];
  }
  GlossyLights lights;
  lights.fill(g, moments, directions);
  const MomentLightPlanes p = lights.planes();
  for (std::size_t i = 0; i < g.node.size(); ++i) {
    const std::uint32_t k = g.node[i];
    const std::array<float, 9> m = moment_floats(moments[k]);
    for (std::size_t c = 0; c < 9; ++c) EXPECT_EQ(p.plane[c][i], m[c]);
    EXPECT_EQ(p.plane[9][i], static_cast<float>(directions[k].x));
    EXPECT_EQ(p.plane[10][i], static_cast<float>(directions[k].y));
    EXPECT_EQ(p.plane[11][i], static_cast<float>(directions[k].z));
  }
}

}  // namespace
}  // namespace relight
