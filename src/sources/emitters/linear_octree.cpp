#include "sources/emitters/linear_octree.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace relight {

namespace {

constexpr std::uint32_t kCellsPerAxis = 1u << kOctreeMaxLevel;

// The 10 bits of v moved to bits 0, 3, 6, …, 27.
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Index of the level-10 cell along one axis; outside [0, 1) clamped (NaN to 0).
std::uint32_t axis_cell(double u) {
  const double t = u * kCellsPerAxis;
  if (!(t > 0)) return 0;
  if (t >= kCellsPerAxis - 1) return kCellsPerAxis - 1;
  return static_cast<std::uint32_t>(t);
}

}  // namespace

int octree_level_for_radius(double side, double radius) {
  int level = 0;
  while (level < kOctreeMaxLevel && std::ldexp(side, -(level + 1)) >= 2 * radius) ++level;
  return level;
}

LinearOctree::LinearOctree(std::span<const Vec3> points) : min_corner_{0, 0, 0}, side_(1) {
  if (points.empty()) return;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  const Vec3 centre = (lo + hi) * 0.5;
  const Vec3 extent = hi - lo;
  const double widest = std::max({extent.x, extent.y, extent.z});
  if (widest > 0) {
    side_ = widest * (1 + 1e-3);
  } else {  // one point (or all coincident): a small cube about it
    side_ = 1e-3 * (1 + std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)}));
  }
  min_corner_ = centre - Vec3{1, 1, 1} * (0.5 * side_);
}

LinearOctree::LinearOctree(Vec3 min_corner, double side) : min_corner_(min_corner), side_(side) {
  if (!(side > 0) || !std::isfinite(side)) {
    throw std::invalid_argument("LinearOctree: the root's side must be positive");
  }
}

LinearOctree::Cell LinearOctree::cell(Vec3 p) const {
  const Vec3 u = (p - min_corner_) / side_;
  return {axis_cell(u.x), axis_cell(u.y), axis_cell(u.z)};
}

std::uint32_t LinearOctree::morton(Cell c) {
  return spread_bits(c.x) | (spread_bits(c.y) << 1) | (spread_bits(c.z) << 2);
}

std::uint32_t LinearOctree::key(Vec3 p, int level) const {
  if (level < 0 || level > kOctreeMaxLevel) {
    throw std::out_of_range("LinearOctree::key: level outside 0..10");
  }
  return (1u << (3 * level)) | (morton(cell(p)) >> (3 * (kOctreeMaxLevel - level)));
}

void LinearOctree::insert(std::uint32_t sample_id, Vec3 centre, double radius) {
  const double r = std::max(radius, 0.0);
  const int level = level_for_radius(r);
  const int shift = kOctreeMaxLevel - level;
  const Vec3 half{r, r, r};
  const Cell lo = cell(centre - half);
  const Cell hi = cell(centre + half);
  for (std::uint32_t z = lo.z >> shift; z <= hi.z >> shift; ++z) {
    for (std::uint32_t y = lo.y >> shift; y <= hi.y >> shift; ++y) {
      for (std::uint32_t x = lo.x >> shift; x <= hi.x >> shift; ++x) {
        // Level-L indices interleave into the low 3L bits: the node's code below the sentinel.
        nodes_[(1u << (3 * level)) | morton({x, y, z})].push_back(sample_id);
      }
    }
  }
  occupied_levels_ |= 1u << level;
}

}  // namespace relight
