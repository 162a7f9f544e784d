#include "sources/environment/glossy_nodes.h"

namespace relight {

GlossyNodes glossy_nodes(const DirectionTree& tree, double cos_half_angle) {
  const std::size_t leaves = tree.leaf_count();
  GlossyNodes g;
  g.first.assign(2 * leaves, GlossyNodes::kNone);
  g.last.assign(2 * leaves, GlossyNodes::kNone);
  g.within.assign(2 * leaves, GlossyNodes::kNone);
  std::vector<std::uint8_t> split(2 * leaves, 0);
  // Depth first, the lower child first: the stopping nodes come in leaf order.
  std::vector<std::uint32_t> stack{1};
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    if (k < leaves && tree.cos_half_angle[k] < cos_half_angle) {
      split[k] = 1;
      stack.push_back(2 * k + 1);
      stack.push_back(2 * k);
      continue;
    }
    g.first[k] = static_cast<std::uint32_t>(g.node.size());
    g.last[k] = g.first[k] + 1;
    g.node.push_back(k);
  }
  // A split node's range is its children's, which come after it in heap order.
  for (std::size_t k = leaves; k-- > 1;) {
    if (split[k] == 0) continue;
    g.first[k] = g.first[2 * k];
    g.last[k] = g.last[2 * k + 1];
  }
  // Below the split: the holder of the parent, or the parent where it is a split node.
  for (std::size_t k = 2; k < 2 * leaves; ++k) {
    const std::size_t parent = k / 2;
    if (g.within[parent] != GlossyNodes::kNone) {
      g.within[k] = g.within[parent];
    } else if (split[parent] == 0 && g.first[parent] != GlossyNodes::kNone) {
      g.within[k] = g.first[parent];
    }
  }
  return g;
}

std::array<float, 9> moment_floats(const RgbMoment& m) {
  return {m.r[0], m.r[1], m.r[2], m.g[0], m.g[1], m.g[2], m.b[0], m.b[1], m.b[2]};
}

void GlossyLights::fill(const GlossyNodes& nodes, std::span<const RgbMoment> moments,
                        std::span<const Vec3> directions) {
  for (std::vector<float>& p : plane_) p.resize(nodes.node.size());
  for (std::size_t i = 0; i < nodes.node.size(); ++i) {
    const std::uint32_t k = nodes.node[i];
    const std::array<float, 9> m = moment_floats(moments[k]);
    for (std::size_t c = 0; c < 9; ++c) plane_[c][i] = m[c];
    plane_[9][i] = static_cast<float>(directions[k].x);
    plane_[10][i] = static_cast<float>(directions[k].y);
    plane_[11][i] = static_cast<float>(directions[k].z);
  }
}

MomentLightPlanes GlossyLights::planes() const {
  MomentLightPlanes p;
  for (std::size_t i = 0; i < 12; ++i) p.plane[i] = plane_[i].data();
  return p;
}

}  // namespace relight
