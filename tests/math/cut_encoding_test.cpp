// Height-encoded binary cuts (math/cut_encoding.h): cuts appended to one store give back every
// node and its visibility; 5 bits a node against the index encoding's 17; a store is checked
// whole on reading (a flipped height is caught); a node list that is not a cut is refused
// before anything is appended.
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "math/cut_encoding.h"
#include "math/direction_cut.h"
#include "math/direction_tree.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(4096, 5));
  return t;
}

// Visible above a tilted horizon through `up`.
DirectionCut horizon_cut(Vec3 up, double threshold) {
  std::vector<float> v(tree().leaf_count());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = dot(tree().leaves[i], up) > 0.1 ? 1.0f : 0.0f;
  return make_direction_cut(tree(), v, threshold);
}

TEST(CutEncoding, EveryNodeAndItsVisibilityComeBackFromFiveBits) {
  HeightCuts store = make_height_cuts(tree());
  std::vector<DirectionCut> cuts;
  for (const Vec3 up : {Vec3{0, 1, 0}, Vec3{1, 0.2, 0}, Vec3{-0.3, -1, 0.5}}) {
    cuts.push_back(horizon_cut(normalize(up), 0));
    append_cut(store, cuts.back());
  }
  const HeightCutsView view = store.view();
  ASSERT_NO_THROW(check_height_cuts(view));
  ASSERT_EQ(view.cut_count(), 3u);
  std::uint64_t nodes = 0;
  for (std::size_t c = 0; c < cuts.size(); ++c) {
    std::vector<std::uint32_t> visible;
    for (std::size_t i = 0; i < cuts[c].nodes.size(); ++i) {
      if (cuts[c].values[i] == 1) visible.push_back(cuts[c].nodes[i]);
    }
    std::vector<std::uint32_t> read;
    view.for_each_visible(c, [&](std::uint32_t node, int h) {
      EXPECT_EQ(h, tree().height(node));
      read.push_back(node);
    });
    EXPECT_EQ(read, visible) << c;
    nodes += cuts[c].nodes.size();
  }
  ASSERT_EQ(view.node_count(), nodes);
  // The nodes' bytes, without the cuts' starts that both encodings keep.
  const auto starts = static_cast<double>(view.first.size() * sizeof(std::uint64_t));
  const double ratio = (static_cast<double>(view.bytes()) - starts) /
                       (static_cast<double>(index_encoded_bytes(view)) - starts);
  std::printf("%llu nodes: %llu bytes height encoded, %llu index encoded (%.3f)\n",
              static_cast<unsigned long long>(nodes), static_cast<unsigned long long>(view.bytes()),
              static_cast<unsigned long long>(index_encoded_bytes(view)), ratio);
  EXPECT_NEAR(ratio, 5.0 / 17.0, 0.01);
}

TEST(CutEncoding, ADamagedStoreIsRefusedWhenChecked) {
  HeightCuts store = make_height_cuts(tree());
  append_cut(store, horizon_cut({0, 1, 0}, 0));
  HeightCuts damaged = store;
  damaged.heights[3] ^= 0x10;  // one node's height off by one
  EXPECT_THROW(check_height_cuts(damaged.view()), std::invalid_argument);
  damaged = store;
  damaged.visible.pop_back();
  EXPECT_THROW(check_height_cuts(damaged.view()), std::invalid_argument);
}

TEST(CutEncoding, NodesThatAreNotACutAreRefusedBeforeAnythingIsAppended) {
  HeightCuts store = make_height_cuts(tree());
  DirectionCut cut = horizon_cut({0, 1, 0}, 0);
  cut.nodes.pop_back();  // a leaf range left uncovered
  cut.values.pop_back();
  EXPECT_THROW(append_cut(store, cut), std::invalid_argument);
  EXPECT_EQ(store.view().node_count(), 0u);
  EXPECT_TRUE(store.heights.empty());
  DirectionCut swapped = horizon_cut({0, 1, 0}, 0);
  std::swap(swapped.nodes[0], swapped.nodes[1]);
  EXPECT_THROW(append_cut(store, swapped), std::invalid_argument);
}

}  // namespace
}  // namespace relight
