// The merge with counters (math/cut_merge.h) against the same operations leaf by leaf: eight
// binary cuts of caps about nearby axes (as the samples of a visibility cut field around a
// point) interpolated with trilinear-like weights, and a horizon cut times two such
// interpolations, equal at every leaf, and the same product taken in two steps; a product with
// a cut of ones keeps the cut's nodes; the index encoding merges to the same cuts.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "math/cut_encoding.h"
#include "math/cut_merge.h"
#include "math/direction_cut.h"
#include "math/direction_tree.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(4096, 5));
  return t;
}

// 0 inside the cap of cosine `c` about `axis` (an occluder's silhouette), 1 elsewhere.
std::vector<float> cap(Vec3 axis, double c) {
  std::vector<float> v(tree().leaf_count());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = dot(tree().leaves[i], axis) > c ? 0.0f : 1.0f;
  return v;
}

// The value of a ValueCut at every leaf.
std::vector<float> leaves_of(const ValueCut& cut) {
  std::vector<float> out;
  for (std::size_t i = 0; i < cut.size(); ++i) {
    out.insert(out.end(), std::size_t{1} << cut.height[i], cut.value[i]);
  }
  return out;
}

// Asserts that `out` is, exactly at every leaf, the operands' weighted sum of `leaf_values` taken
// in the operands' order.
void expect_weighted_sum_at_every_leaf(const ValueCut& out,
                                       const std::vector<WeightedCut>& operands,
                                       const std::vector<std::vector<float>>& leaf_values) {
  const std::vector<float> got = leaves_of(out);
  ASSERT_EQ(got.size(), tree().leaf_count());
  for (std::size_t i = 0; i < got.size(); ++i) {
    float expected = 0;
    for (std::size_t s = 0; s < operands.size(); ++s) {
      expected += operands[s].weight * leaf_values[s][i];
    }
    ASSERT_EQ(got[i], expected) << i;
  }
}

TEST(CutMerge, EightInterpolatedCutsEqualTheWeightedSumAtEveryLeaf) {
  HeightCuts store = make_height_cuts(tree());
  std::vector<std::vector<float>> leaf_values;
  for (int s = 0; s < 8; ++s) {
    leaf_values.push_back(cap(normalize(Vec3{0.2 * (s & 1), 1, 0.15 * (s >> 1)}), 0.9 - 0.01 * s));
    append_cut(store, make_direction_cut(tree(), leaf_values.back(), 0));
  }
  const HeightCutsView view = store.view();
  std::vector<WeightedCut> operands;
  const float w[8] = {0.3f, 0.1f, 0.05f, 0.15f, 0.1f, 0.1f, 0.12f, 0.08f};
  for (std::size_t s = 0; s < 8; ++s) operands.push_back({&view, s, w[s]});
  ValueCut out;
  interpolate_cuts(operands, out);
  // Exactly: a node's value is the sum of its visible operands' weights in the operands' order
  // (up to eight operands by a table of those sums), the same floats as this sum.
  expect_weighted_sum_at_every_leaf(out, operands, leaf_values);
  if (HasFatalFailure()) return;
  // The previous methods' index encoding of the same cuts: each node's height from its index, the
  // same merge giving the same cut.
  const IndexCuts indexed = index_encoded(view);
  const IndexCutsView iv = indexed.view();
  ASSERT_EQ(iv.node_count(), view.node_count());
  for (std::uint64_t k = 0; k < view.node_count(); ++k) {
    ASSERT_EQ(iv.height(k), view.height(k)) << k;
    ASSERT_EQ(iv.is_visible(k), view.is_visible(k)) << k;
  }
  EXPECT_EQ(iv.bytes(), index_encoded_bytes(view));
  std::vector<WeightedIndexCut> index_operands;
  for (std::size_t s = 0; s < 8; ++s) index_operands.push_back({&iv, s, w[s]});
  ValueCut from_index;
  interpolate_cuts(index_operands, from_index);
  EXPECT_EQ(from_index.height, out.height);
  EXPECT_EQ(from_index.value, out.value);
  std::printf("8 cuts of %llu nodes in all interpolated into %zu nodes\n",
              static_cast<unsigned long long>(view.node_count()), out.size());
  EXPECT_LT(out.size(), view.node_count());
}

TEST(CutMerge, TenInterpolatedCutsBeyondTheTableEqualTheWeightedSumAtEveryLeaf) {
  HeightCuts store = make_height_cuts(tree());
  std::vector<std::vector<float>> leaf_values;
  for (int s = 0; s < 10; ++s) {
    leaf_values.push_back(cap(normalize(Vec3{0.1 * (s % 3), 1, 0.12 * (s / 3)}), 0.92 - 0.01 * s));
    append_cut(store, make_direction_cut(tree(), leaf_values.back(), 0));
  }
  const HeightCutsView view = store.view();
  std::vector<WeightedCut> operands;
  for (std::size_t s = 0; s < 10; ++s) operands.push_back({&view, s, 0.05f + 0.01f * s});
  ValueCut out;
  interpolate_cuts(operands, out);
  expect_weighted_sum_at_every_leaf(out, operands, leaf_values);
}

TEST(CutMerge, ARunPushedAtOnceIsTheCutItsLeavesMakeOneByOne) {
  // Runs of 0s, 1s and halves of lengths 1 to 300 at every alignment, after a few leaves.
  std::uint32_t state = 12345;
  const auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (int trial = 0; trial < 200; ++trial) {
    ValueCut one_by_one, runs;
    std::uint64_t leaf = 0;
    while (leaf < 4096) {
      const std::uint64_t count = std::min<std::uint64_t>(1 + next() % 300, 4096 - leaf);
      const float v = static_cast<float>(next() % 3) * 0.5f;
      for (std::uint64_t i = 0; i < count; ++i) push_cut_node(one_by_one, leaf + i, 0, v);
      push_cut_run(runs, leaf, count, v);
      leaf += count;
    }
    ASSERT_EQ(runs.height, one_by_one.height) << trial;
    ASSERT_EQ(runs.value, one_by_one.value) << trial;
  }
}

TEST(CutMerge, AProductEqualsTheLeafProductAndOnesChangeNothing) {
  HeightCuts store = make_height_cuts(tree());
  std::vector<float> horizon(tree().leaf_count());
  const Vec3 up = normalize(Vec3{0.1, 1, -0.2});
  for (std::size_t i = 0; i < horizon.size(); ++i) {
    horizon[i] = dot(tree().leaves[i], up) > 0 ? 1.0f : 0.0f;
  }
  append_cut(store, make_direction_cut(tree(), horizon, 0));
  const std::vector<float> a = cap(normalize(Vec3{0.5, 1, 0}), 0.95);
  const std::vector<float> b = cap(normalize(Vec3{-0.2, 0.6, 0.3}), 0.97);
  append_cut(store, make_direction_cut(tree(), a, 0));
  append_cut(store, make_direction_cut(tree(), b, 0));
  const HeightCutsView view = store.view();
  ValueCut fa, fb, ones, out;
  const WeightedCut wa{&view, 1, 0.75f}, wb{&view, 2, 1.0f};
  interpolate_cuts(std::span(&wa, 1), fa);
  interpolate_cuts(std::span(&wb, 1), fb);
  const ValueCut* factors[] = {&fa, &fb};
  multiply_cuts(view, 0, factors, out);
  const std::vector<float> got = leaves_of(out);
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_NEAR(got[i], horizon[i] * 0.75f * a[i] * b[i], 1e-6) << i;
  }
  // A product kept and multiplied again (a drag: the others' product times the moving one's
  // field) equals the product of all three at once.
  ValueCut partial, again;
  const ValueCut* first[] = {&fa};
  multiply_cuts(view, 0, first, partial);
  const ValueCut* rest[] = {&partial, &fb};
  multiply_cuts(rest, again);
  EXPECT_EQ(again.height, out.height);
  EXPECT_EQ(again.value, out.value);
  // Times a cut of ones: the horizon cut's own nodes, merged back where they were.
  ones.height = {static_cast<std::uint8_t>(tree().height(1))};
  ones.value = {1.0f};
  const ValueCut* one[] = {&ones};
  multiply_cuts(view, 0, one, out);
  EXPECT_EQ(out.size(), view.first[1] - view.first[0]);
  std::uint64_t visited = 0;
  for_each_node(out, static_cast<std::uint32_t>(tree().leaf_count()),
                [&](std::uint32_t node, float) {
                  EXPECT_GE(node, 1u);
                  visited += std::uint64_t{1} << tree().height(node);
                });
  EXPECT_EQ(visited, tree().leaf_count());
}

}  // namespace
}  // namespace relight
