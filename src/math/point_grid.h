// Points on or in the unit ball hashed into a uniform 3-D grid over [−1, 1]³: the
// neighbours of a point within one cell, and the nearest point. The direction tree
// (math/direction_tree.h) relaxes its directions with the neighbours, and a direction is
// binned to its nearest leaf — the leaf's Voronoi cell on the sphere — when an environment is
// clustered on the tree (light/environment_clusters.h). Cells are stored densely in
// compressed rows. Pinned by tests/math/point_grid_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

class PointGrid {
 public:
  // Throws std::invalid_argument unless cell > 0.
  PointGrid(std::span<const Vec3> points, double cell);

  // Calls visit(i) for every point i in the 27 cells around p (every point within `cell` of
  // p, and some farther).
  template <typename Visit>
  void near(Vec3 p, const Visit& visit) const {
    const int x = coordinate(p.x), y = coordinate(p.y), z = coordinate(p.z);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const int cx = x + dx, cy = y + dy, cz = z + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= side_ || cy >= side_ || cz >= side_) continue;
          const std::size_t c = index(cx, cy, cz);
          for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) visit(members_[k]);
        }
      }
    }
  }

  // The index of the point nearest p (the first of equals); exact: when no point lies in
  // the cells around p, every point is compared.
  std::uint32_t nearest(Vec3 p) const;

 private:
  int coordinate(double v) const;
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(x) * static_cast<std::size_t>(side_) +
            static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(side_) +
           static_cast<std::size_t>(z);
  }

  double cell_;
  int side_;
  std::vector<Vec3> points_;
  std::vector<std::uint32_t> first_;    // per cell: [first_[c], first_[c + 1]) in members_
  std::vector<std::uint32_t> members_;  // point indices, cell by cell
};

}  // namespace relight
