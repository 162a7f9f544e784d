#include "math/direction_cut.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace relight {

DirectionCut make_direction_cut(const DirectionTree& tree, std::span<const float> leaf_values,
                                double threshold) {
  const std::size_t n = tree.leaf_count();
  if (leaf_values.size() != n || !(threshold >= 0)) {
    throw std::invalid_argument("direction cut: one value per leaf and a threshold >= 0");
  }
  // Bottom up: each node's mean, smallest and largest leaf.
  std::vector<double> mean(2 * n), low(2 * n), high(2 * n);
  for (std::size_t i = 0; i < n; ++i) mean[n + i] = low[n + i] = high[n + i] = leaf_values[i];
  for (std::size_t k = n - 1; k >= 1; --k) {
    mean[k] = 0.5 * (mean[2 * k] + mean[2 * k + 1]);
    low[k] = std::min(low[2 * k], low[2 * k + 1]);
    high[k] = std::max(high[2 * k], high[2 * k + 1]);
  }
  // Top down, left child first: the cut's nodes come out in leaf order.
  DirectionCut cut;
  std::vector<std::size_t> stack{1};
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    stack.pop_back();
    const double error = std::max(high[k] - mean[k], mean[k] - low[k]);
    if (k >= n || error <= threshold) {
      cut.nodes.push_back(static_cast<std::uint32_t>(k));
      cut.values.push_back(static_cast<float>(mean[k]));
      continue;
    }
    stack.push_back(2 * k + 1);
    stack.push_back(2 * k);
  }
  return cut;
}

float cut_value_at(const DirectionTree& tree, const DirectionCut& cut, std::size_t leaf) {
  const std::size_t n = tree.leaf_count();
  // The cut node above leaf i: the one whose leaf range holds it (nodes in leaf order).
  const auto it = std::upper_bound(cut.nodes.begin(), cut.nodes.end(), leaf,
                                   [&](std::size_t i, std::uint32_t node) {
                                     const int h = tree.height(node);
                                     return i < (std::size_t{node} << h) - n;
                                   });
  return cut.values.at(static_cast<std::size_t>(it - cut.nodes.begin()) - 1);
}

}  // namespace relight
