// A cut of a direction tree (math/direction_tree.h) approximating a function sampled at its
// leaves (the capture paper, papers/003, §V, after Akerlund et al. 2007): every inner
// node holds the mean of the leaves below it and the error of standing in for them — the
// largest |leaf − mean| — and the cut is the set of highest nodes whose error is within a
// threshold, found from the root down, so that every leaf is within the threshold of its cut
// node's value. A node whose leaves agree has error 0: a binary function (visibility) keeps its
// edges exactly at threshold 0 and merges only uniform regions, the sharpness the paper's
// all-frequency shadows need. The cut's nodes lie in leaf order and cover every leaf once;
// Σ value · leaves below = Σ leaves. Pinned by tests/math/direction_cut_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/direction_tree.h"

namespace relight {

struct DirectionCut {
  std::vector<std::uint32_t> nodes;  // heap indices (direction_tree.h), in leaf order
  std::vector<float> values;         // per node: the mean of the leaves below it
};

// Throws std::invalid_argument unless there is one value per leaf and threshold ≥ 0.
DirectionCut make_direction_cut(const DirectionTree& tree, std::span<const float> leaf_values,
                                double threshold);

// The cut's value at leaf i.
float cut_value_at(const DirectionTree& tree, const DirectionCut& cut, std::size_t leaf);

}  // namespace relight
