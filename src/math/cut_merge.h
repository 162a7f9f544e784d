// Products and interpolations of cuts of the direction tree by the paper's merge with counters
// (Iwasaki et al., Cyberworlds, §V.A.3, Fig. 6, Steps 1–4: the capture paper, papers/003). Every
// operand lists its nodes in leaf order by height alone (math/cut_encoding.h), so the operands are
// walked together without a node index: a pointer and a counter per operand (Step 1), the operation
// applied to the pointed nodes and stored at the lowest of their heights h_min (Step 2), a pointer
// at h_min advanced and the others' counters raised by 2^h_min, a pointer advanced when its counter
// reaches 2^h of its node (Step 3), until every pointer is past its cut's last node (Step 4). Each
// counter is kept as the leaf its pointed node ends at (the leaf reached plus what is left of the
// node): the smallest end is the output node's, and a pointer moves when its end is reached — the
// same steps, without raising every other counter at each output node, which makes interpolations
// and products faster (measured: docs/decisions.md; bench/cuts_bench.cpp). The result is the
// coarsest common refinement of the operands, with siblings of equal value merged again, so a
// product of visibilities stays as compact as its edges allow. Pinned by
// tests/math/cut_merge_test.cpp (against the same operations leaf by leaf).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "math/cut_encoding.h"

namespace relight {

// A cut with fractional values (an interpolated visibility, a product): per node in leaf order
// its height and value.
struct ValueCut {
  std::vector<std::uint8_t> height;
  std::vector<float> value;

  void clear() {
    height.clear();
    value.clear();
  }
  std::size_t size() const { return height.size(); }
};

// Appends the node of height h starting at leaf `first_leaf` (the end of `out`) with value v,
// merging it with its left sibling while they are of equal height and value.
// Inline: called once a leaf where cuts are made leaf by leaf
// (sources/environment/environment_objects.h).
inline void push_cut_node(ValueCut& out, std::uint64_t first_leaf, int h, float v) {
  while (!out.height.empty() && out.height.back() == h && out.value.back() == v &&
         (first_leaf & ((std::uint64_t{2} << h) - 1)) == (std::uint64_t{1} << h)) {
    out.height.pop_back();
    out.value.pop_back();
    first_leaf -= std::uint64_t{1} << h;
    ++h;
  }
  out.height.push_back(static_cast<std::uint8_t>(h));
  out.value.push_back(v);
}

// Appends leaves first … first + count − 1 (the end of `out`), all of value v, as the fewest
// nodes push_cut_node makes of them one by one.
inline void push_cut_run(ValueCut& out, std::uint64_t first, std::uint64_t count, float v) {
  while (count > 0) {
    const int h = std::min(std::countr_zero(first), static_cast<int>(std::bit_width(count)) - 1);
    push_cut_node(out, first, h, v);
    first += std::uint64_t{1} << h;
    count -= std::uint64_t{1} << h;
  }
}

// The value of every leaf of `cut` (N leaves) into `leaves`.
void expand_cut(const ValueCut& cut, std::span<float> leaves);

// A stored binary cut (cut `cut` of `cuts`) with its weight in an interpolation; View the
// encoding (math/cut_encoding.h): the paper's height encoding, or the previous methods' index
// encoding as the baseline (the same merge, each node's height derived from its index).
template <typename View>
struct WeightedCutOf {
  const View* cuts = nullptr;
  std::size_t cut = 0;
  float weight = 0;
};
using WeightedCut = WeightedCutOf<HeightCutsView>;
using WeightedIndexCut = WeightedCutOf<IndexCutsView>;

// out = Σ weight · cut, over at most 16 operands of the same tree.
void interpolate_cuts(std::span<const WeightedCut> operands, ValueCut& out);
void interpolate_cuts(std::span<const WeightedIndexCut> operands, ValueCut& out);

// out = the stored binary cut (cuts, cut) times every factor. N is the tree's leaf count.
void multiply_cuts(const HeightCutsView& cuts, std::size_t cut,
                   std::span<const ValueCut* const> factors, ValueCut& out);
void multiply_cuts(const IndexCutsView& cuts, std::size_t cut,
                   std::span<const ValueCut* const> factors, ValueCut& out);
// out = the product of 1 to 16 value cuts (each non-empty) of the same tree.
void multiply_cuts(std::span<const ValueCut* const> factors, ValueCut& out);

// Calls visit(heap_node, value) for every node of `cut`, in leaf order (N leaves). Always
// inlined, so that what a visitor sums stays in registers (measured: docs/decisions.md).
template <typename Visit>
[[gnu::always_inline]] inline void for_each_node(const ValueCut& cut, std::uint32_t leaf_count,
                                                 const Visit& visit) {
  std::uint64_t leaf = 0;
  for (std::size_t i = 0; i < cut.height.size(); ++i) {
    const int h = cut.height[i];
    visit(static_cast<std::uint32_t>((leaf_count + leaf) >> h), cut.value[i]);
    leaf += std::uint64_t{1} << h;
  }
}

}  // namespace relight
