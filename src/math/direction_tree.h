// The direction set and binary tree of the all-frequency visibility cuts (Iwasaki,
// Dobashi, Nishita et al., the capture paper papers/003, §V.A.1, after Akerlund et al. 2007):
// N directions spread uniformly over the unit sphere by point repulsion (the paper: 32,768),
// and a complete binary tree over them whose leaves are the directions, so that a cut — a set
// of nodes covering every leaf once — is a piecewise-constant function on the sphere.
//
// Directions: a spherical Fibonacci lattice, then `iterations` steps of repulsion among
// neighbours closer than three mean spacings (force (p − q)/|p − q|³ projected on the tangent
// plane, step at most a tenth of the spacing, renormalised). The lattice is nearly uniform
// already: at 32,768 directions nearest neighbours lie 0.0181–0.0195 apart before the 20 steps
// and 0.0183–0.0203 after (hexagonal packing: 0.0210); caps of 256 expected directions hold
// within 1.6 % of it. Tree: recursive median splits along the
// widest extent of a node's directions (the largest of x, y, z ranges), so that siblings are
// compact caps of equal counts; N must be a power of two, the tree is complete and stored in
// heap order (node 1 the root, children 2k and 2k + 1, leaves N … 2N − 1 in leaf order), and
// each node keeps its mean direction and a cone containing its leaves.
// Pinned by tests/math/direction_tree_test.cpp.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace relight {

// N uniform directions by point repulsion (N ≥ 4).
std::vector<Vec3> repulsed_directions(std::size_t count, int iterations = 20);

struct DirectionTree {
  std::vector<Vec3> leaves;  // the directions in leaf order: leaf i is node N + i
  // Per node (index 0 unused): unit mean direction and the cosine of a cone about it that
  // contains every leaf below the node.
  std::vector<Vec3> axis;
  std::vector<double> cos_half_angle;
  std::size_t leaf_count() const { return leaves.size(); }
  // The height of node k: 0 for a leaf, log2 N for the root.
  int height(std::size_t node) const {
    return std::bit_width(leaves.size()) - std::bit_width(node);
  }
};

// Throws std::invalid_argument unless directions.size() is a power of two ≥ 2.
DirectionTree build_direction_tree(std::vector<Vec3> directions);
// The tree whose leaves are `leaves` in this order (a built tree's, as a file stores them): the
// nodes' axes and cones. Throws as build_direction_tree.
DirectionTree direction_tree_over_leaves(std::vector<Vec3> leaves);

}  // namespace relight
