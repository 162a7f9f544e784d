#include "import/floor_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace relight {
namespace {

struct Point2 {
  double x = 0, z = 0;
};

bool inside(const std::array<Vec3, 3>& t, Point2 p) {
  const auto edge = [](Vec3 a, Vec3 b, Point2 q) {
    return (b.x - a.x) * (q.z - a.z) - (b.z - a.z) * (q.x - a.x);
  };
  const double d0 = edge(t[0], t[1], p), d1 = edge(t[1], t[2], p), d2 = edge(t[2], t[0], p);
  const bool negative = d0 < 0 || d1 < 0 || d2<0, positive = d0> 0 || d1 > 0 || d2 > 0;
  return !(negative && positive);
}

bool in_floor(std::span<const std::array<Vec3, 3>> footprint, Point2 p) {
  return std::any_of(footprint.begin(), footprint.end(),
                     [&](const std::array<Vec3, 3>& t) { return inside(t, p); });
}

// Whether the disc of radius `border` about p lies in the floor: its centre and 32 points of its
// rim (the rim between two of them bulges at most border · (1 − cos(π/32)), 0.5 % of it, past a
// corner). Testing the floor itself, not its outline, keeps an edge that two triangles share
// only in part (a T-junction, common in exported floors) from counting as a wall.
bool clear_of_walls(std::span<const std::array<Vec3, 3>> footprint, Point2 p, double border) {
  constexpr int kRim = 32;
  if (!in_floor(footprint, p)) return false;
  for (int k = 0; k < kRim && border > 0; ++k) {
    const double a = 2 * std::numbers::pi * k / kRim;
    if (!in_floor(footprint, {p.x + border * std::cos(a), p.z + border * std::sin(a)}))
      return false;
  }
  return true;
}

}  // namespace

std::vector<Vec3> floor_grid(std::span<const std::array<Vec3, 3>> footprint, double height,
                             double spacing, double border) {
  if (footprint.empty() || !(spacing > 0)) return {};
  Point2 lo{footprint[0][0].x, footprint[0][0].z}, hi = lo;
  for (const auto& t : footprint)
    for (const Vec3& v : t) {
      lo = {std::min(lo.x, v.x), std::min(lo.z, v.z)};
      hi = {std::max(hi.x, v.x), std::max(hi.z, v.z)};
    }
  const auto count = [&](double extent) {
    return static_cast<int>(std::floor(extent / spacing + 1e-9));
  };
  const int nx = count(hi.x - lo.x), nz = count(hi.z - lo.z);
  // The lattice centred on the extent: equal margins on both sides of each axis.
  const double x0 = lo.x + 0.5 * (hi.x - lo.x - (nx - 1) * spacing);
  const double z0 = lo.z + 0.5 * (hi.z - lo.z - (nz - 1) * spacing);
  std::vector<Vec3> points;
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Point2 p{x0 + i * spacing, z0 + j * spacing};
      if (!clear_of_walls(footprint, p, border)) continue;
      points.push_back({p.x, height, p.z});
    }
  }
  return points;
}

}  // namespace relight
