// Cuts of the 32,768-direction tree (math/direction_cut.h): a visibility function keeps its
// edge exactly at threshold 0 with far fewer nodes than leaves; a smooth V · cos stays within
// the threshold of every leaf and sums to the leaves' sum; a large threshold leaves the root.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "math/direction_cut.h"
#include "math/direction_tree.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(32768));
  return t;
}

TEST(DirectionCut, AVisibilityEdgeStaysExactAndUniformRegionsMerge) {
  const DirectionTree& t = tree();
  // Seen where the direction is more than 20° above a tilted horizon.
  const Vec3 up = normalize(Vec3{0.3, 1, 0.2});
  std::vector<float> v(t.leaf_count());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = dot(t.leaves[i], up) > 0.34 ? 1.0f : 0.0f;
  const DirectionCut cut = make_direction_cut(t, v, 0);
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(cut_value_at(t, cut, i), v[i]) << i;
  std::printf("visibility cut: %zu nodes for %zu leaves\n", cut.nodes.size(), v.size());
  EXPECT_LT(cut.nodes.size(), v.size() / 8);
  // Leaf order, covering every leaf once.
  std::size_t next = 0;
  for (const std::uint32_t node : cut.nodes) {
    const int h = t.height(node);
    ASSERT_EQ((std::size_t{node} << h) - t.leaf_count(), next);
    next += std::size_t{1} << h;
  }
  EXPECT_EQ(next, v.size());
}

TEST(DirectionCut, ASmoothFunctionStaysWithinTheThresholdAndKeepsItsSum) {
  const DirectionTree& t = tree();
  const Vec3 n = normalize(Vec3{0.2, 1, -0.4});
  std::vector<float> v(t.leaf_count());
  double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = static_cast<float>(std::max(0.0, dot(t.leaves[i], n)));
    sum += v[i];
  }
  for (const double threshold : {0.01, 0.05}) {
    const DirectionCut cut = make_direction_cut(t, v, threshold);
    double worst = 0, total = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      worst = std::max(worst, std::abs(double{cut_value_at(t, cut, i)} - v[i]));
    }
    for (std::size_t c = 0; c < cut.nodes.size(); ++c) {
      total +=
          double{cut.values[c]} * static_cast<double>(std::size_t{1} << t.height(cut.nodes[c]));
    }
    std::printf("cos cut at %.2f: %zu nodes, worst leaf %.4f off\n", threshold, cut.nodes.size(),
                worst);
    EXPECT_LE(worst, threshold + 1e-6);
    EXPECT_NEAR(total, sum, 1e-5 * sum);
  }
  const DirectionCut root = make_direction_cut(t, v, 1.0);
  ASSERT_EQ(root.nodes.size(), 1u);
  EXPECT_EQ(root.nodes[0], 1u);
  EXPECT_THROW(make_direction_cut(t, std::vector<float>(7), 0), std::invalid_argument);
}

}  // namespace
}  // namespace relight
