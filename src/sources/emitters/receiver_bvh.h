// The bounding volume hierarchy over the receivers that drives near-field sampling (the
// Sun 2005 §3.2.2, Algorithm 3.3): top-down, each node split at the median of its
// receivers' coordinates along the longest axis of its box (a balanced, nearly full binary
// tree), flattened into one array. Each node keeps the two attributes the run time needs:
// its sample position, the mean of its receivers (where the incident radiance is sampled),
// and its radius, half the diagonal of its axis-aligned box (the oracle's r, Eq. 3.3, and the
// sample's valid domain).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

struct ReceiverBvhNode {
  Vec3 box_min, box_max;
  Vec3 sample_position;                // mean of the receivers in the node
  double radius = 0;                   // half the diagonal of the box
  std::uint32_t first = 0, count = 0;  // receivers order[first, first + count)
  std::int32_t left = -1, right = -1;  // children (both −1 for a leaf)
  bool leaf() const { return left < 0; }
};

struct ReceiverBvh {
  std::vector<ReceiverBvhNode> nodes;  // nodes[0] is the root (when there are receivers)
  std::vector<std::uint32_t> order;    // receiver indices, each node's a contiguous range
};

// Leaves hold at most `leaf_size` receivers (≥ 1).
ReceiverBvh build_receiver_bvh(std::span<const Vec3> points, std::uint32_t leaf_size = 1);

}  // namespace relight
