// Ear clipping in the polygon's Newell plane: each step cuts off a convex corner whose
// triangle holds no other corner, so the triangles tile the polygon and share its winding.
// O(n^2) per polygon, which is fine for the face sizes mesh files use.
#include "scene/mesh_import_polygon.h"

#include <cmath>

namespace relight {
namespace {

struct Point2 {
  double x = 0, y = 0;
};

// Twice the signed area of (a, b, c); positive when counter-clockwise.
double orient(Point2 a, Point2 b, Point2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool same_point(Point2 a, Point2 b) {
  return a.x == b.x && a.y == b.y;
}

// p inside or on the boundary of the counter-clockwise triangle (a, b, c).
bool inside_or_on(Point2 p, Point2 a, Point2 b, Point2 c) {
  return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

void fan(std::span<const std::uint32_t> corners, std::vector<Triangle>& out) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    out.push_back({corners[0], corners[k], corners[k + 1]});
  }
}

}  // namespace

void triangulate_polygon(std::span<const std::uint32_t> corners, std::span<const Vec3> positions,
                         std::vector<Triangle>& out) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  if (n == 3) {
    out.push_back({corners[0], corners[1], corners[2]});
    return;
  }

  // Newell's normal: robust for non-planar and concave polygons.
  Vec3 normal;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = positions[corners[i]];
    const Vec3 q = positions[corners[(i + 1) % n]];
    normal += Vec3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
  }
  const double normal_length = length(normal);
  if (!(normal_length > 0) || !std::isfinite(normal_length)) {
    fan(corners, out);
    return;
  }
  normal = normal / normal_length;
  // (u, v, normal) is right-handed, so counter-clockwise about `normal` is positive in 2D.
  const Vec3 helper = std::abs(normal.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalize(cross(helper, normal));
  const Vec3 v = cross(normal, u);

  std::vector<Point2> flat(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = positions[corners[i]];
    flat[i] = {dot(p, u), dot(p, v)};
  }

  std::vector<std::size_t> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = i;

  while (ring.size() > 3) {
    const std::size_t m = ring.size();
    bool clipped = false;
    // Starting at corner 1 makes a convex polygon come out as the fan around corner 0.
    for (std::size_t step = 0; step < m && !clipped; ++step) {
      const std::size_t k = (step + 1) % m;
      const std::size_t a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
      if (orient(flat[a], flat[b], flat[c]) <= 0) continue;  // reflex or flat corner
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j) {
        const std::size_t p = ring[j];
        if (p == a || p == b || p == c) continue;
        if (same_point(flat[p], flat[a]) || same_point(flat[p], flat[b]) ||
            same_point(flat[p], flat[c])) {
          continue;
        }
        empty = !inside_or_on(flat[p], flat[a], flat[b], flat[c]);
      }
      if (!empty) continue;
      out.push_back({corners[a], corners[b], corners[c]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) {  // self-intersecting or degenerate remainder
      std::vector<std::uint32_t> rest(ring.size());
      for (std::size_t i = 0; i < ring.size(); ++i) rest[i] = corners[ring[i]];
      fan(rest, out);
      return;
    }
  }
  out.push_back({corners[ring[0]], corners[ring[1]], corners[ring[2]]});
}

}  // namespace relight
