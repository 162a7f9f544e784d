#include "math/direction_tree.h"

#include "math/point_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace relight {

std::vector<Vec3> repulsed_directions(std::size_t count, int iterations) {
  if (count < 4) throw std::invalid_argument("repulsed_directions: at least 4 directions");
  // Spherical Fibonacci lattice.
  std::vector<Vec3> p(count);
  const double golden = kPi * (3 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1 - (2 * static_cast<double>(i) + 1) / static_cast<double>(count);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = golden * static_cast<double>(i);
    p[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  const double spacing = std::sqrt(4 * kPi / static_cast<double>(count));
  const double reach = 3 * spacing;
  std::vector<Vec3> next(count);
  for (int it = 0; it < iterations; ++it) {
    const PointGrid grid(p, reach);
    {
      for (std::size_t i = 0; i < count; ++i) {
        Vec3 force{0, 0, 0};
        grid.near(p[i], [&](std::uint32_t j) {
          if (j == i) return;
          const Vec3 d = p[i] - p[j];
          const double l2 = dot(d, d);
          if (l2 <= 0 || l2 >= reach * reach) return;
          force += d * (1 / (l2 * std::sqrt(l2)));
        });
        force -= p[i] * dot(force, p[i]);  // tangential
        const double f = length(force);
        // A step of at most a tenth of the spacing along the force.
        const double step =
            f > 0 ? std::min(0.1 * spacing, 0.1 * spacing * spacing * spacing * f) : 0;
        next[i] = f > 0 ? normalize(p[i] + force * (step / f)) : p[i];
      }
    }
    p.swap(next);
  }
  return p;
}

DirectionTree build_direction_tree(std::vector<Vec3> directions) {
  const std::size_t n = directions.size();
  if (n < 2 || !std::has_single_bit(n)) {
    throw std::invalid_argument("direction tree: the directions' count must be a power of two");
  }
  // Recursive median splits, in place: node k covers [lo, hi) of `directions`.
  struct Span {
    std::size_t node, lo, hi;
  };
  std::vector<Span> stack{{1, 0, n}};
  while (!stack.empty()) {
    const Span s = stack.back();
    stack.pop_back();
    if (s.hi - s.lo == 1) continue;
    Vec3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    for (std::size_t i = s.lo; i < s.hi; ++i) {
      const Vec3 d = directions[i];
      lo = {std::min(lo.x, d.x), std::min(lo.y, d.y), std::min(lo.z, d.z)};
      hi = {std::max(hi.x, d.x), std::max(hi.y, d.y), std::max(hi.z, d.z)};
    }
    const Vec3 extent = hi - lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto coordinate = [axis](const Vec3& d) {
      return axis == 0 ? d.x : (axis == 1 ? d.y : d.z);
    };
    const std::size_t mid = s.lo + (s.hi - s.lo) / 2;
    const auto first = directions.begin() + static_cast<std::ptrdiff_t>(s.lo);
    std::nth_element(first, directions.begin() + static_cast<std::ptrdiff_t>(mid),
                     directions.begin() + static_cast<std::ptrdiff_t>(s.hi),
                     [&](const Vec3& a, const Vec3& b) { return coordinate(a) < coordinate(b); });
    stack.push_back({2 * s.node, s.lo, mid});
    stack.push_back({2 * s.node + 1, mid, s.hi});
  }
  return direction_tree_over_leaves(std::move(directions));
}

DirectionTree direction_tree_over_leaves(std::vector<Vec3> leaves) {
  const std::size_t n = leaves.size();
  if (n < 2 || !std::has_single_bit(n)) {
    throw std::invalid_argument("direction tree: the directions' count must be a power of two");
  }
  DirectionTree tree;
  tree.axis.assign(2 * n, {0, 0, 0});
  tree.cos_half_angle.assign(2 * n, 1.0);
  tree.leaves = std::move(leaves);
  // Axes and cones, leaves up.
  for (std::size_t i = 0; i < n; ++i) tree.axis[n + i] = tree.leaves[i];
  for (std::size_t k = n - 1; k >= 1; --k) {
    // The cone about the mean of the leaves below: leaves k·2^h − N … (k + 1)·2^h − N − 1.
    const int h = tree.height(k);
    const std::size_t first = (k << h) - n, count = std::size_t{1} << h;
    Vec3 mean{0, 0, 0};
    for (std::size_t i = first; i < first + count; ++i) mean += tree.leaves[i];
    tree.axis[k] = length(mean) > 0 ? normalize(mean) : tree.leaves[first];
    double c = 1;
    for (std::size_t i = first; i < first + count; ++i)
      c = std::min(c, dot(tree.axis[k], tree.leaves[i]));
    tree.cos_half_angle[k] = c;
  }
  return tree;
}

}  // namespace relight
