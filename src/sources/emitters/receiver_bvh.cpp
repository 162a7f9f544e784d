#include "sources/emitters/receiver_bvh.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace relight {

namespace {

struct Builder {
  std::span<const Vec3> points;
  std::uint32_t leaf_size;
  ReceiverBvh bvh;

  // Fills node `index` (already allocated) for order[first, first + count) and splits it.
  void build(std::size_t index, std::uint32_t first, std::uint32_t count) {
    Vec3 lo = points[bvh.order[first]], hi = lo, sum{0, 0, 0};
    for (std::uint32_t k = first; k < first + count; ++k) {
      const Vec3 p = points[bvh.order[k]];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      sum = sum + p;
    }
    ReceiverBvhNode node;
    node.box_min = lo;
    node.box_max = hi;
    node.sample_position = sum * (1.0 / count);
    node.radius = 0.5 * length(hi - lo);
    node.first = first;
    node.count = count;
    bvh.nodes[index] = node;
    if (count <= leaf_size) return;
    // The longest axis, split at the median (nth_element: the two halves need no order).
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const std::uint32_t half = count / 2;
    const auto begin = bvh.order.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t a, std::uint32_t b) {
      return points[a][axis] < points[b][axis];
    });
    const auto left = static_cast<std::int32_t>(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[index].left = left;
    bvh.nodes[index].right = left + 1;
    build(static_cast<std::size_t>(left), first, half);
    build(static_cast<std::size_t>(left) + 1, first + half, count - half);
  }
};

}  // namespace

ReceiverBvh build_receiver_bvh(std::span<const Vec3> points, std::uint32_t leaf_size) {
  if (leaf_size < 1) throw std::invalid_argument("receiver BVH: leaf_size must be >= 1");
  Builder b{points, leaf_size, {}};
  if (points.empty()) return {};
  b.bvh.order.resize(points.size());
  std::iota(b.bvh.order.begin(), b.bvh.order.end(), 0u);
  b.bvh.nodes.reserve(2 * points.size());
  b.bvh.nodes.resize(1);
  b.build(0, 0, static_cast<std::uint32_t>(points.size()));
  return std::move(b.bvh);
}

}  // namespace relight
