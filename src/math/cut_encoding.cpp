#include "math/cut_encoding.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace relight {

HeightCuts make_height_cuts(const DirectionTree& tree) {
  if (tree.leaf_count() > (std::size_t{1} << kMaxCutHeight)) {
    throw std::invalid_argument("height-encoded cuts: at most 2^15 directions");
  }
  HeightCuts cuts;
  cuts.leaf_count = static_cast<std::uint32_t>(tree.leaf_count());
  cuts.first.push_back(0);
  return cuts;
}

void reserve_height_cuts(HeightCuts& store, std::uint64_t cuts, std::uint64_t nodes) {
  const std::uint64_t total = store.first.back() + nodes;
  store.first.reserve(store.first.size() + cuts);
  store.heights.reserve((total + 1) / 2);
  store.visible.reserve((total + 7) / 8);
}

void append_cut(HeightCuts& cuts, const DirectionCut& cut) {
  const std::uint64_t n = cuts.leaf_count;
  const int log_n = std::bit_width(n) - 1;
  // Checked whole before anything is appended.
  std::vector<int> height(cut.nodes.size());
  std::uint64_t leaf = 0;
  for (std::size_t i = 0; i < cut.nodes.size(); ++i) {
    const std::uint64_t node = cut.nodes[i];
    if (node == 0 || node >= 2 * n) throw std::invalid_argument("cut node outside the tree");
    height[i] = log_n - (std::bit_width(node) - 1);
    // The node must start at `leaf`: its first leaf is node · 2^h − N.
    if ((node << height[i]) - n != leaf) throw std::invalid_argument("cut nodes not in leaf order");
    leaf += std::uint64_t{1} << height[i];
  }
  if (leaf != n || cut.values.size() != cut.nodes.size()) {
    throw std::invalid_argument("cut does not cover every leaf once");
  }
  for (std::size_t i = 0; i < cut.nodes.size(); ++i) {
    const std::uint64_t k = cuts.first.back() + i;
    if ((k & 1) == 0) {
      cuts.heights.push_back(static_cast<std::uint8_t>(height[i]));
    } else {
      cuts.heights.back() = static_cast<std::uint8_t>(cuts.heights.back() | (height[i] << 4));
    }
    if ((k & 7) == 0) cuts.visible.push_back(0);
    if (cut.values[i] >= 0.5f) {
      cuts.visible.back() = static_cast<std::uint8_t>(cuts.visible.back() | (1u << (k & 7)));
    }
  }
  cuts.first.push_back(cuts.first.back() + cut.nodes.size());
}

std::uint64_t HeightCutsView::bytes() const {
  return heights.size() + visible.size() + first.size() * sizeof(std::uint64_t);
}

void check_height_cuts(const HeightCutsView& cuts) {
  const std::uint64_t n = cuts.leaf_count;
  if (n < 2 || !std::has_single_bit(n) || n > (std::uint64_t{1} << kMaxCutHeight)) {
    throw std::invalid_argument("cuts: the directions' count is not a power of two <= 32768");
  }
  const std::uint64_t nodes = cuts.node_count();
  if (cuts.first.empty() || cuts.first.front() != 0 || cuts.visible.size() != (nodes + 7) / 8 ||
      cuts.heights.size() != (nodes + 1) / 2 ||
      !std::is_sorted(cuts.first.begin(), cuts.first.end())) {
    throw std::invalid_argument("cuts: the cuts' starts, heights and values disagree");
  }
  const int log_n = std::bit_width(n) - 1;
  for (std::size_t c = 0; c < cuts.cut_count(); ++c) {
    std::uint64_t leaf = 0;
    for (std::uint64_t k = cuts.first[c]; k < cuts.first[c + 1]; ++k) {
      const int h = cuts.height(k);
      // A node of height h starts at a multiple of 2^h.
      if (h > log_n || (leaf & ((std::uint64_t{1} << h) - 1)) != 0) {
        throw std::invalid_argument("cuts: cut " + std::to_string(c) + " is not a cut of the tree");
      }
      leaf += std::uint64_t{1} << h;
    }
    if (leaf != n) {
      throw std::invalid_argument("cuts: cut " + std::to_string(c) + " does not cover the leaves");
    }
  }
}

std::uint64_t IndexCutsView::bytes() const {
  return (node_count() * 17 + 7) / 8 + first.size() * sizeof(std::uint64_t);
}

IndexCutsView IndexCuts::view() const {
  return {leaf_count, first, index, visible, static_cast<int>(std::bit_width(leaf_count)) - 1};
}

IndexCuts index_encoded(const HeightCutsView& cuts) {
  IndexCuts out;
  out.leaf_count = cuts.leaf_count;
  out.first.assign(cuts.first.begin(), cuts.first.end());
  out.index.reserve(cuts.node_count());
  for (std::size_t c = 0; c < cuts.cut_count(); ++c) {
    std::uint64_t leaf = 0;
    for (std::uint64_t k = cuts.first[c]; k < cuts.first[c + 1]; ++k) {
      const int h = cuts.height(k);
      out.index.push_back(static_cast<std::uint16_t>((cuts.leaf_count + leaf) >> h));
      leaf += std::uint64_t{1} << h;
    }
  }
  out.visible.assign(cuts.visible.begin(), cuts.visible.end());
  return out;
}

std::uint64_t index_encoded_bytes(const HeightCutsView& cuts) {
  return IndexCutsView{cuts.leaf_count, cuts.first, {}, {}, 0}.bytes();
}

}  // namespace relight
