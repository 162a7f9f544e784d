// Binary visibility cuts of the direction tree stored many to an array (Iwasaki et al.,
// Cyberworlds, §V.A.2, Fig. 5: the capture paper, papers/003). A cut lists its nodes in
// leaf order and every root-to-leaf path holds exactly one of them, so a node is known from
// the leaf where it starts and its height h (edges down to a leaf: 0 … 15 for 2¹⁵ leaves): it
// is node (N + leaf) >> h of the heap (math/direction_tree.h), and the next node starts 2^h
// leaves on. The paper's height encoding keeps h in 4 bits and the node's visibility in 1 bit;
// the previous methods (Akerlund et al. 2007; Cheslack-Postava et al. 2008) keep the node's
// 2-byte index instead of its height (17 bits a node against 5), built here too (IndexCuts) as
// the baseline of the height encoding's size and of the merge's speed (math/cut_merge.h takes
// both; bench/cuts_bench.cpp times them).
//
// Storage: heights two a byte, low nibble first; visibility bits eight a byte, lowest bit
// first; both indexed by the node's place among all the cuts' nodes; cut c's nodes are
// [first[c], first[c + 1]). A cut's value of a node is rounded to 0 or 1 when appended: cuts
// of binary visibility made at a threshold below ½ (math/direction_cut.h) merge only nodes
// whose leaves agree to within it, and a merged node takes its majority's value.
// Pinned by tests/math/cut_encoding_test.cpp.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/direction_cut.h"
#include "math/direction_tree.h"

namespace relight {

inline constexpr int kMaxCutHeight = 15;  // 4 bits

// Height-encoded binary cuts as stored (a file's sections or a HeightCuts).
struct HeightCutsView {
  std::uint32_t leaf_count = 0;           // N, a power of two ≤ 2^15
  std::span<const std::uint64_t> first;   // per cut, into the nodes; cuts + 1 entries
  std::span<const std::uint8_t> heights;  // 4 bits a node
  std::span<const std::uint8_t> visible;  // 1 bit a node

  std::size_t cut_count() const { return first.empty() ? 0 : first.size() - 1; }
  std::uint64_t node_count() const { return first.empty() ? 0 : first.back(); }
  int height(std::uint64_t node) const { return (heights[node >> 1] >> ((node & 1) << 2)) & 0xF; }
  bool is_visible(std::uint64_t node) const {
    return ((visible[node >> 3] >> (node & 7)) & 1) != 0;
  }
  // Calls visit(heap_node, height) for every visible node of cut c, in leaf order.
  template <typename Visit>
  void for_each_visible(std::size_t c, const Visit& visit) const {
    std::uint64_t leaf = 0;
    for (std::uint64_t k = first[c]; k < first[c + 1]; ++k) {
      const int h = height(k);
      if (is_visible(k)) visit(static_cast<std::uint32_t>((leaf_count + leaf) >> h), h);
      leaf += std::uint64_t{1} << h;
    }
  }
  // Bytes of the height encoding: heights, visibility bits and the cuts' starts.
  std::uint64_t bytes() const;
};

// Throws std::invalid_argument when the view's sizes disagree (a damaged file): the starts
// not increasing from 0, the heights or bits not one per node, a height above log2 N, or a
// cut whose heights do not cover the N leaves exactly.
void check_height_cuts(const HeightCutsView& cuts);

struct HeightCuts {
  std::uint32_t leaf_count = 0;
  std::vector<std::uint64_t> first;
  std::vector<std::uint8_t> heights;
  std::vector<std::uint8_t> visible;

  HeightCutsView view() const { return {leaf_count, first, heights, visible}; }
};

// An empty store for cuts of `tree`; throws std::invalid_argument when it has more than 2^15
// leaves.
HeightCuts make_height_cuts(const DirectionTree& tree);

// Appends `cut`, each value rounded to 0 or 1. Throws std::invalid_argument when its nodes are
// not a cut of the store's tree in leaf order.
void append_cut(HeightCuts& cuts, const DirectionCut& cut);

// Appends `count` cuts in index order, made a window at a time: `make(first, cuts)` fills
// cuts[i] with cut first + i (in parallel, as the caller likes), and they are encoded before the
// next window, so that unencoded cuts (8 bytes a node, against under 2 encoded) are never held for
// more than a window.
inline constexpr std::size_t kCutWindow = 8192;
template <class Make>
void append_cuts_in_windows(HeightCuts& store, std::size_t count, Make make) {
  constexpr std::size_t kWindow = kCutWindow;
  std::vector<DirectionCut> cuts(std::min(count, kWindow));
  for (std::size_t first = 0; first < count; first += kWindow) {
    const std::span<DirectionCut> window = std::span(cuts).first(std::min(kWindow, count - first));
    make(first, window);
    for (DirectionCut& cut : window) {
      append_cut(store, cut);
      cut = {};
    }
  }
}

// The bytes of `cuts` cuts of `nodes` nodes in all, height encoded (as HeightCutsView::bytes).
inline std::uint64_t height_cuts_bytes(std::uint64_t cuts, std::uint64_t nodes) {
  return (nodes + 1) / 2 + (nodes + 7) / 8 + (cuts + 1) * sizeof(std::uint64_t);
}

// Room for `cuts` more cuts of `nodes` nodes in all, so that a store filled to a predicted size
// never holds its old and its grown arrays at once.
void reserve_height_cuts(HeightCuts& store, std::uint64_t cuts, std::uint64_t nodes);

// The previous methods' encoding (Akerlund et al. 2007; Cheslack-Postava et al. 2008): each
// node by its 2-byte heap index and 1 visibility bit, the height derived from the index
// (log2 N − ⌊log2 index⌋).
struct IndexCutsView {
  std::uint32_t leaf_count = 0;
  std::span<const std::uint64_t> first;   // per cut, into the nodes; cuts + 1 entries
  std::span<const std::uint16_t> index;   // the heap index of every node
  std::span<const std::uint8_t> visible;  // 1 bit a node
  int log_n = 0;                          // log2 leaf_count

  std::size_t cut_count() const { return first.empty() ? 0 : first.size() - 1; }
  std::uint64_t node_count() const { return first.empty() ? 0 : first.back(); }
  int height(std::uint64_t node) const {
    return log_n - (std::bit_width(static_cast<unsigned>(index[node])) - 1);
  }
  bool is_visible(std::uint64_t node) const {
    return ((visible[node >> 3] >> (node & 7)) & 1) != 0;
  }
  // Bytes: 17 bits a node and the cuts' starts.
  std::uint64_t bytes() const;
};

struct IndexCuts {
  std::uint32_t leaf_count = 0;
  std::vector<std::uint64_t> first;
  std::vector<std::uint16_t> index;
  std::vector<std::uint8_t> visible;

  IndexCutsView view() const;
};

// The same cuts index encoded.
IndexCuts index_encoded(const HeightCutsView& cuts);

// Bytes of the same cuts index encoded (IndexCutsView::bytes), without encoding them.
std::uint64_t index_encoded_bytes(const HeightCutsView& cuts);

}  // namespace relight
