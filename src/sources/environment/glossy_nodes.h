// The direction tree's nodes as a glossy view sums them (the capture paper, papers/003, §V.B,
// Eq. 3, as sources/environment/environment_lighting.h shades a vertex toward an eye): the BRDF is
// evaluated once a node of the view's split — the nodes where a walk from the root stops, a cone
// within the view's node size (3°) or a leaf — so that a node of open sky does not put a quadrant's
// light at one direction of a narrow lobe, and a cut's nodes finer than that (a shadow's edge, a
// product of visibility fields) are summed into the split node that holds them. The split nodes
// cover the sphere once, and in leaf order every node at or above them owns a contiguous range of
// them. Their lights are kept in planes of floats (material/specular_lobe_sum.h), so a vertex's
// visible nodes become a few long ranges of one array summed eight at a time.
// Pinned by tests/sources/environment/glossy_nodes_test.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "light/environment_clusters.h"
#include "material/specular_lobe_sum.h"
#include "math/direction_tree.h"
#include "math/vec3.h"

namespace relight {

struct GlossyNodes {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> node;  // where the split from the root stops, in leaf order
  // Per tree node k (heap order, 0 unused), at or above the split: its split is
  // node[first[k], last[k]), and within[k] is kNone. Below the split: within[k] is the index
  // of the split node holding k, and first[k] and last[k] are kNone.
  std::vector<std::uint32_t> first, last, within;
};

// The split of `tree` into cones within `cos_half_angle`: a node is split while it is not a
// leaf and its cone's cosine is below it.
GlossyNodes glossy_nodes(const DirectionTree& tree, double cos_half_angle);

// The nine floats of a moment in the planes' order: M_r (x, y, z), M_g, M_b.
std::array<float, 9> moment_floats(const RgbMoment& m);

// The lights of the split's nodes: moments[node] and directions[node] (one a tree node) in
// planes (material/specular_lobe_sum.h), one entry a split node.
class GlossyLights {
 public:
  void fill(const GlossyNodes& nodes, std::span<const RgbMoment> moments,
            std::span<const Vec3> directions);
  MomentLightPlanes planes() const;

 private:
  std::array<std::vector<float>, 12> plane_;
};

}  // namespace relight
