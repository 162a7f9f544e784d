// A portal's convex pieces and their cones; see portal_outline.h.
#include "sources/portals/portal_outline.h"

#include <algorithm>
#include <cmath>

#include "math/frame.h"

namespace relight {

namespace {

constexpr double kPlaneTolerance = 1e-6;  // of unit normals, and metres of offset
constexpr double kAreaTolerance = 1e-6;   // relative: the hull's area against the triangles'

struct Plane {
  Vec3 normal;
  double offset = 0;
};

struct Point2 {
  double x = 0, y = 0;
};

double turn(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull, counter-clockwise, without collinear points (Andrew 1979): a turn within
// `tolerance` of straight is dropped.
std::vector<Point2> convex_hull(std::vector<Point2> points, double tolerance) {
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  });
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point2& p : points) {  // lower chain
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= tolerance) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {  // upper chain
    while (k >= lower && turn(hull[k - 2], hull[k - 1], *it) <= tolerance) --k;
    hull[k++] = *it;
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

double polygon_area(const std::vector<Point2>& p) {
  double twice = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Point2& a = p[k];
    const Point2& b = p[(k + 1) % p.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * std::abs(twice);
}

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

std::vector<PortalPiece> portal_pieces(const PreparedMesh& mesh,
                                       std::span<const std::uint32_t> triangles) {
  // Group by plane.
  std::vector<Plane> planes;
  std::vector<std::vector<std::uint32_t>> by_plane;
  for (const std::uint32_t t : triangles) {
    const Triangle& tri = mesh.triangles[t];
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    const Vec3 face = cross(b - a, c - a);
    if (!(length(face) > 0)) continue;
    const Vec3 normal = normalize(face);
    const double offset = dot(normal, a);
    std::size_t p = 0;
    while (p < planes.size() && !(dot(planes[p].normal, normal) > 1 - kPlaneTolerance &&
                                  std::abs(planes[p].offset - offset) < kPlaneTolerance)) {
      ++p;
    }
    if (p == planes.size()) {
      planes.push_back({normal, offset});
      by_plane.emplace_back();
    }
    by_plane[p].push_back(t);
  }
  std::vector<PortalPiece> pieces;
  std::vector<std::uint32_t> parent(mesh.positions.size());
  for (std::size_t p = 0; p < planes.size(); ++p) {
    // Within the plane, by shared vertices.
    for (const std::uint32_t t : by_plane[p]) {
      for (const std::uint32_t v : mesh.triangles[t]) parent[v] = v;
    }
    for (const std::uint32_t t : by_plane[p]) {
      const Triangle& tri = mesh.triangles[t];
      const std::uint32_t root = find(parent, tri[0]);
      parent[find(parent, tri[1])] = root;
      parent[find(parent, tri[2])] = root;
    }
    std::vector<std::vector<std::uint32_t>> groups;
    std::vector<std::uint32_t> roots;
    for (const std::uint32_t t : by_plane[p]) {
      const std::uint32_t root = find(parent, mesh.triangles[t][0]);
      const auto it = std::find(roots.begin(), roots.end(), root);
      if (it == roots.end()) {
        roots.push_back(root);
        groups.push_back({t});
      } else {
        groups[static_cast<std::size_t>(it - roots.begin())].push_back(t);
      }
    }
    const Frame frame = frame_from_normal(planes[p].normal);
    for (const std::vector<std::uint32_t>& group : groups) {
      std::vector<Point2> points;
      double area = 0, extent = 0;
      for (const std::uint32_t t : group) {
        const Triangle& tri = mesh.triangles[t];
        const Vec3 a = mesh.positions[tri[0]];
        area += 0.5 * length(cross(mesh.positions[tri[1]] - a, mesh.positions[tri[2]] - a));
        for (const std::uint32_t v : tri) {
          const Vec3 q = mesh.positions[v];
          points.push_back({dot(q, frame.t), dot(q, frame.b)});
          extent = std::max({extent, std::abs(points.back().x), std::abs(points.back().y)});
        }
      }
      const std::vector<Point2> hull = convex_hull(points, 1e-12 * extent * extent);
      if (hull.size() >= 3 && std::abs(polygon_area(hull) - area) <= kAreaTolerance * area) {
        PortalPiece piece;
        for (const Point2& h : hull) {
          piece.push_back(frame.t * h.x + frame.b * h.y + frame.n * planes[p].offset);
        }
        pieces.push_back(std::move(piece));
        continue;
      }
      for (const std::uint32_t t : group) {
        const Triangle& tri = mesh.triangles[t];
        pieces.push_back({mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]});
      }
    }
  }
  return pieces;
}

void PieceCones::reset(Vec3 origin, const std::vector<PortalPiece>& pieces) {
  planes_.clear();
  ends_.clear();
  for (const PortalPiece& piece : pieces) {
    const Vec3 face = cross(piece[1] - piece[0], piece[2] - piece[0]);
    if (!(std::abs(dot(normalize(face), piece[0] - origin)) > 1e-9)) continue;
    Vec3 centre{0, 0, 0};
    for (const Vec3& v : piece) centre = centre + (v - origin);
    for (std::size_t k = 0; k < piece.size(); ++k) {
      const Vec3 plane = cross(piece[k] - origin, piece[(k + 1) % piece.size()] - origin);
      planes_.push_back(dot(plane, centre) >= 0 ? plane : plane * -1.0);
    }
    ends_.push_back(static_cast<std::uint32_t>(planes_.size()));
  }
}

bool PieceCones::contains(Vec3 direction) const {
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends_) {
    bool inside = true;
    for (std::uint32_t k = begin; k < end && inside; ++k) inside = dot(planes_[k], direction) >= 0;
    if (inside) return true;
    begin = end;
  }
  return false;
}

}  // namespace relight
