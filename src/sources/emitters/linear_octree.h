// The linear octree of Sun 2005 §3.3.5: the near-field samples are found by
// hashing instead of pointer traversal. A node's key is its locational code, a leading 1
// (the sentinel bit) followed by 3 bits per level, the octant at that level in ZYX order (the
// 3D form of the (0.Y₁X₁Y₂X₂…) of Fig. 3.5), so the parent of key k is k >> 3. 32-bit keys
// hold 1 + 3·10 bits: levels 0 (the root, key 1) to 10. A sample whose valid domain is a
// sphere of radius r (§3.3.3) goes to level L = ⌊log₂(s/r) − 1⌋ (clamped to 0..10), where
// the node side s/2^L is at least 2r, so the sphere's bounding box overlaps at most 8 nodes;
// it is stored in each of them. A query computes the point's key at every level and looks
// each up: every sample whose sphere contains the point is visited exactly once (the point
// lies in one node per level and a sample lives at one level). The caller tests the sphere.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "math/vec3.h"

namespace relight {

inline constexpr int kOctreeMaxLevel = 10;

// L = ⌊log₂(side/radius) − 1⌋ clamped to 0..kOctreeMaxLevel: the deepest level whose node
// side side/2^L is still >= 2·radius (radius <= 0: the deepest level).
int octree_level_for_radius(double side, double radius);

class LinearOctree {
 public:
  // The root: the bounding box of the points to reconstruct made cubic about its centre and
  // enlarged by 1e-3 of its side (a minimum side for coincident points; unit cube if empty).
  explicit LinearOctree(std::span<const Vec3> points);
  // The root given exactly: the cube [min_corner, min_corner + side]³ (side > 0).
  LinearOctree(Vec3 min_corner, double side);

  Vec3 min_corner() const { return min_corner_; }
  double side() const { return side_; }
  int level_for_radius(double radius) const { return octree_level_for_radius(side_, radius); }

  // Locational code of the node at `level` (0..10) containing p; p outside the root is
  // clamped to it (the far faces belong to the last node).
  std::uint32_t key(Vec3 p, int level) const;

  // Stores sample_id in every node at level_for_radius(radius) that the box
  // [centre − radius, centre + radius]³ overlaps.
  void insert(std::uint32_t sample_id, Vec3 centre, double radius);

  // visit(sample_id) for every id stored in a node that contains p, level 0 first, in
  // insertion order within a node. Safe to call concurrently (read-only).
  template <class Visitor>
  void for_each_candidate(Vec3 p, Visitor&& visit) const {
    const std::uint32_t deepest = morton(cell(p));
    for (int level = 0; level <= kOctreeMaxLevel; ++level) {
      if ((occupied_levels_ & (1u << level)) == 0) continue;
      const int shift = 3 * (kOctreeMaxLevel - level);
      const auto node = nodes_.find((1u << (3 * level)) | (deepest >> shift));
      if (node == nodes_.end()) continue;
      for (const std::uint32_t id : node->second) visit(id);
    }
  }

  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Cell {
    std::uint32_t x, y, z;  // at level 10, each in 0..1023
  };
  Cell cell(Vec3 p) const;
  static std::uint32_t morton(Cell c);  // ZYX-interleaved 30 bits, level 1's octant on top

  Vec3 min_corner_;
  double side_;
  std::uint32_t occupied_levels_ = 0;  // bit L: some sample lives at level L
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> nodes_;
};

}  // namespace relight
