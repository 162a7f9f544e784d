#include "sources/environment/self_visibility.h"

#include <vector>

namespace relight {

DirectionCut self_visibility_cut(const Occluders& occluders, const DirectionTree& tree, Vec3 origin,
                                 Vec3 n, double threshold, std::uint64_t& rays) {
  std::vector<float> values(tree.leaf_count(), 0.0f);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double c = dot(n, tree.leaves[i]);
    if (c <= 0) continue;
    ++rays;
    if (!occluders.occluded({origin, tree.leaves[i]})) values[i] = 1.0f;
  }
  return make_direction_cut(tree, values, threshold);
}

}  // namespace relight
