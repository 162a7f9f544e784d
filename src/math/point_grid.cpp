#include "math/point_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace relight {

PointGrid::PointGrid(std::span<const Vec3> points, double cell)
    : cell_(cell), side_(0), points_(points.begin(), points.end()) {
  if (!(cell > 0)) throw std::invalid_argument("point grid: the cell must be > 0");
  side_ = static_cast<int>(std::ceil(2 / cell)) + 1;
  const std::size_t cells =
      static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_) * side_;
  std::vector<std::size_t> of(points_.size());
  first_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Vec3 p = points_[i];
    of[i] = index(coordinate(p.x), coordinate(p.y), coordinate(p.z));
    ++first_[of[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
  members_.resize(points_.size());
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    members_[fill[of[i]]++] = static_cast<std::uint32_t>(i);
  }
}

int PointGrid::coordinate(double v) const {
  return std::clamp(static_cast<int>((v + 1) / cell_), 0, side_ - 1);
}

std::uint32_t PointGrid::nearest(Vec3 p) const {
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t out = 0;
  const auto consider = [&](std::uint32_t i) {
    const Vec3 d = points_[i] - p;
    const double l2 = dot(d, d);
    if (l2 < best || (l2 == best && i < out)) {
      best = l2;
      out = i;
    }
  };
  near(p, consider);
  // A point in the 27 cells within `cell_` of p is the nearest; otherwise one farther out may
  // be nearer than those found.
  if (best > cell_ * cell_) {
    for (std::uint32_t i = 0; i < points_.size(); ++i) consider(i);
  }
  return out;
}

}  // namespace relight
