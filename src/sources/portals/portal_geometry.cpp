#include "sources/portals/portal_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/input_error.h"

namespace relight {

std::vector<PortalGeometry> portal_geometry(const Scene& scene, const PreparedMesh& mesh) {
  const std::vector<int> portal_of_material = scene.portal_of_material();
  std::vector<PortalGeometry> portals(scene.portals.size());
  for (std::size_t p = 0; p < scene.portals.size(); ++p) portals[p].name = scene.portals[p].name;
  std::vector<Vec3> weighted_normal(portals.size(), Vec3{0, 0, 0});
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const int p = portal_of_material[mesh.triangle_material[t]];
    if (p < 0) continue;
    const Triangle& tri = mesh.triangles[t];
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    const Vec3 face = cross(b - a, c - a);
    const double area = 0.5 * length(face);
    PortalGeometry& g = portals[static_cast<std::size_t>(p)];
    g.triangles.push_back(t);
    g.area += area;
    g.centre = g.centre + (a + b + c) * (area / 3.0);
    weighted_normal[static_cast<std::size_t>(p)] =
        weighted_normal[static_cast<std::size_t>(p)] + face * 0.5;
  }
  for (std::size_t p = 0; p < portals.size(); ++p) {
    PortalGeometry& g = portals[p];
    if (g.triangles.empty() || g.area <= 0) {
      fail_input(scene.file.string() + ": portal \"" + g.name + "\"",
                 "its materials have no triangles with area in the geometry");
    }
    g.centre = g.centre * (1.0 / g.area);
    g.pieces = portal_pieces(mesh, g.triangles);
    const double n = length(weighted_normal[p]);
    g.normal = n > 1e-6 * g.area ? weighted_normal[p] * (1.0 / n) : Vec3{0, 0, 0};
    // Diameter over the distinct vertices (portals are small: the quadratic loop is cheap
    // next to the transfer they feed).
    std::vector<std::uint32_t> vertices;
    for (std::uint32_t t : g.triangles) {
      for (std::uint32_t v : mesh.triangles[t]) vertices.push_back(v);
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      for (std::size_t j = i + 1; j < vertices.size(); ++j) {
        g.diameter =
            std::max(g.diameter, length(mesh.positions[vertices[i]] - mesh.positions[vertices[j]]));
      }
    }
  }
  return portals;
}

std::vector<std::uint8_t> portal_vertices(const PreparedMesh& mesh,
                                          const std::vector<Material>& materials) {
  std::vector<std::uint8_t> glass(mesh.positions.size(), 0);
  std::vector<std::uint8_t> other(mesh.positions.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    auto& mark = materials.at(mesh.triangle_material[t]).portal ? glass : other;
    for (std::uint32_t v : mesh.triangles[t]) mark[v] = 1;
  }
  for (std::size_t v = 0; v < glass.size(); ++v) glass[v] = glass[v] && !other[v];
  return glass;
}

double shell_direction_error(double diameter, double distance) {
  return distance > 0 ? diameter / (2 * distance) : INFINITY;
}

namespace {

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, §5.1.5).
Vec3 closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = 1 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

double nearest_exterior_distance(Vec3 point, const std::vector<ExteriorGeometry>& exterior) {
  double nearest = INFINITY;
  for (const ExteriorGeometry& object : exterior) {
    const TriangleSoup& g = object.geometry;
    for (const Triangle& t : g.triangles) {
      const Vec3 q =
          closest_point_on_triangle(point, g.positions[t[0]], g.positions[t[1]], g.positions[t[2]]);
      nearest = std::min(nearest, length(q - point));
    }
  }
  return nearest;
}

std::vector<std::string> shell_size_warnings(const Scene& scene,
                                             const std::vector<PortalGeometry>& portals) {
  std::vector<std::string> warnings;
  for (std::size_t p = 0; p < portals.size() && p < scene.portals.size(); ++p) {
    const Portal& portal = scene.portals[p];
    const PortalGeometry& g = portals[p];
    const bool given = portal.exterior_distance > 0;
    const double r =
        given ? portal.exterior_distance : nearest_exterior_distance(g.centre, scene.exterior);
    if (!std::isfinite(r)) continue;
    const double error_deg = shell_direction_error(g.diameter, r) * 180 / kPi;
    if (error_deg <= portal.shell_tolerance_deg) continue;
    char text[512];
    std::snprintf(
        text, sizeof text,
        "portal \"%s\" is %.2f m across and the exterior is %.2f m away (%s): the "
        "shell's direction error l/(2r) = %.1f deg exceeds shell_tolerance_deg %.1f; "
        "split the window into portals of at most %.2f m (interior-scene paper, section 6)",
        g.name.c_str(), g.diameter, r, given ? "exterior_distance" : "nearest exterior geometry",
        error_deg, portal.shell_tolerance_deg, 2 * r * portal.shell_tolerance_deg * kPi / 180);
    warnings.emplace_back(text);
  }
  return warnings;
}

}  // namespace relight
