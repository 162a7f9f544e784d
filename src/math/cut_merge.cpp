#include "math/cut_merge.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace relight {

namespace {

constexpr std::size_t kMaxOperands = 16;
constexpr std::size_t kMaxTabled = 8;  // interpolations of up to 8 cuts sum by a table

// A pointer into one operand (Steps 1 and 3), with the pointed node's height and value read
// once when the pointer moves. View: the stored cuts' encoding (height or index).
template <typename View>
struct Cursor {
  const View* stored = nullptr;      // a stored binary cut, or
  const ValueCut* values = nullptr;  // a cut with values
  std::uint64_t k = 0, end = 0;      // the pointed node and the end
  int h = 0;                         // the pointed node's height
  float v = 0;                       // and value

  void load() {
    if (k >= end) return;
    if (stored != nullptr) {
      h = stored->height(k);
      v = stored->is_visible(k) ? 1.0f : 0.0f;
    } else {
      h = values->height[static_cast<std::size_t>(k)];
      v = values->value[static_cast<std::size_t>(k)];
    }
  }
};

}  // namespace

void expand_cut(const ValueCut& cut, std::span<float> leaves) {
  std::size_t leaf = 0;
  for (std::size_t i = 0; i < cut.size(); ++i) {
    const std::size_t count = std::size_t{1} << cut.height[i];
    std::fill_n(leaves.begin() + static_cast<std::ptrdiff_t>(leaf), count, cut.value[i]);
    leaf += count;
  }
}

namespace {

// Steps 1–4 over `cursors`; op(values of the pointed nodes) is each output node's value. Each
// cursor's counter is kept as the leaf its pointed node ends at: every pointed node contains
// the current leaf, so the smallest of them starts there and ends first, and its end less the
// current leaf is the output node's size (2^h_min).
template <typename View, typename Op>
void merge(std::span<Cursor<View>> cursors, const Op& op, ValueCut& out) {
  out.clear();
  const std::size_t count = cursors.size();
  std::uint64_t ends[kMaxOperands];
  float values[kMaxOperands];
  for (std::size_t j = 0; j < count; ++j) {
    cursors[j].load();
    ends[j] = std::uint64_t{1} << cursors[j].h;
    values[j] = cursors[j].v;
  }
  std::uint64_t leaf = 0;
  while (cursors.front().k < cursors.front().end) {
    std::uint64_t next = ends[0];
    for (std::size_t j = 1; j < count; ++j) next = std::min(next, ends[j]);
    push_cut_node(out, leaf, std::countr_zero(next - leaf),
                  op(std::span<const float>(values, count)));
    leaf = next;
    for (std::size_t j = 0; j < count; ++j) {
      if (ends[j] != next) continue;
      Cursor<View>& c = cursors[j];
      ++c.k;
      c.load();
      ends[j] = next + (std::uint64_t{1} << c.h);
      values[j] = c.v;
    }
  }
}

// As merge, for stored (binary) cuts alone: each output node's value is table[the set of
// operands visible there, operand j as bit j]. Its own loop, as merge taking a values policy for
// both is slower on a chair drag (measured: docs/decisions.md).
template <typename View>
void merge_visible(std::span<Cursor<View>> cursors, const float* table, ValueCut& out) {
  out.clear();
  const std::size_t count = cursors.size();
  std::uint64_t ends[kMaxOperands];
  unsigned visible = 0;
  for (std::size_t j = 0; j < count; ++j) {
    cursors[j].load();
    ends[j] = std::uint64_t{1} << cursors[j].h;
    visible |= (cursors[j].v != 0 ? 1u : 0u) << j;
  }
  std::uint64_t leaf = 0;
  while (cursors.front().k < cursors.front().end) {
    std::uint64_t next = ends[0];
    for (std::size_t j = 1; j < count; ++j) next = std::min(next, ends[j]);
    push_cut_node(out, leaf, std::countr_zero(next - leaf), table[visible]);
    leaf = next;
    for (std::size_t j = 0; j < count; ++j) {
      if (ends[j] != next) continue;
      Cursor<View>& c = cursors[j];
      ++c.k;
      c.load();
      ends[j] = next + (std::uint64_t{1} << c.h);
      visible = (visible & ~(1u << j)) | (c.v != 0 ? 1u : 0u) << j;
    }
  }
}

}  // namespace

namespace {

template <typename View>
void interpolate(std::span<const WeightedCutOf<View>> operands, ValueCut& out) {
  if (operands.empty() || operands.size() > kMaxOperands) {
    throw std::invalid_argument("interpolate_cuts: 1 to 16 operands");
  }
  Cursor<View> cursors[kMaxOperands];
  float weights[kMaxOperands];
  std::size_t count = 0;
  for (const WeightedCutOf<View>& o : operands) {
    // An operand of weight 0 adds nothing but its nodes' boundaries.
    if (o.weight == 0) continue;
    cursors[count].stored = o.cuts;
    cursors[count].k = o.cuts->first[o.cut];
    cursors[count].end = o.cuts->first[o.cut + 1];
    weights[count] = o.weight;
    ++count;
  }
  if (count == 0) {
    const WeightedCutOf<View>& o = operands.front();
    cursors[0].stored = o.cuts;
    cursors[0].k = o.cuts->first[o.cut];
    cursors[0].end = o.cuts->first[o.cut + 1];
    weights[0] = 0;
    count = 1;
  }
  if (count > kMaxTabled) {
    merge(
        std::span<Cursor<View>>(cursors, count),
        [&](std::span<const float> v) {
          float sum = 0;
          for (std::size_t j = 0; j < v.size(); ++j) sum += weights[j] * v[j];
          return sum;
        },
        out);
    return;
  }
  // The stored cuts are binary, so an output node's value is the sum of the weights of the
  // operands visible there: a table by the set of them, each sum taken in the operands' order
  // (the same floats as summing w·v over every operand).
  float table[std::size_t{1} << kMaxTabled];
  table[0] = 0;
  for (std::size_t m = 1; m < (std::size_t{1} << count); ++m) {
    const int top = std::bit_width(m) - 1;
    table[m] = table[m ^ (std::size_t{1} << top)] + weights[top];
  }
  merge_visible(std::span<Cursor<View>>(cursors, count), table, out);
}

// out = Π over the cursors' cuts.
template <typename View>
void multiply(std::span<Cursor<View>> cursors, ValueCut& out) {
  merge(
      cursors,
      [](std::span<const float> v) {
        float p = v[0];
        for (std::size_t j = 1; j < v.size() && p != 0; ++j) p *= v[j];
        return p;
      },
      out);
}

template <typename View>
void multiply_stored(const View& cuts, std::size_t cut, std::span<const ValueCut* const> factors,
                     ValueCut& out) {
  if (factors.size() + 1 > kMaxOperands) {
    throw std::invalid_argument("multiply_cuts: at most 15 factors");
  }
  Cursor<View> cursors[kMaxOperands];
  cursors[0].stored = &cuts;
  cursors[0].k = cuts.first[cut];
  cursors[0].end = cuts.first[cut + 1];
  for (std::size_t j = 0; j < factors.size(); ++j) {
    cursors[j + 1].values = factors[j];
    cursors[j + 1].end = factors[j]->size();
  }
  multiply(std::span<Cursor<View>>(cursors, factors.size() + 1), out);
}

}  // namespace

void interpolate_cuts(std::span<const WeightedCut> operands, ValueCut& out) {
  interpolate(operands, out);
}

void interpolate_cuts(std::span<const WeightedIndexCut> operands, ValueCut& out) {
  interpolate(operands, out);
}

void multiply_cuts(const HeightCutsView& cuts, std::size_t cut,
                   std::span<const ValueCut* const> factors, ValueCut& out) {
  multiply_stored(cuts, cut, factors, out);
}

void multiply_cuts(const IndexCutsView& cuts, std::size_t cut,
                   std::span<const ValueCut* const> factors, ValueCut& out) {
  multiply_stored(cuts, cut, factors, out);
}

void multiply_cuts(std::span<const ValueCut* const> factors, ValueCut& out) {
  if (factors.empty() || factors.size() > kMaxOperands) {
    throw std::invalid_argument("multiply_cuts: 1 to 16 factors");
  }
  Cursor<HeightCutsView> cursors[kMaxOperands];
  for (std::size_t j = 0; j < factors.size(); ++j) {
    cursors[j].values = factors[j];
    cursors[j].end = factors[j]->size();
  }
  multiply(std::span<Cursor<HeightCutsView>>(cursors, factors.size()), out);
}

}  // namespace relight
