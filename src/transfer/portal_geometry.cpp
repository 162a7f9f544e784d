#include "transfer/portal_geometry.h"

#include <algorithm>
#include <cmath>

#include "common/input_error.h"

namespace relight {

std::vector<PortalGeometry> portal_geometry(const Scene& scene, const PreparedMesh& mesh) {
  std::vector<int> portal_of_material(scene.materials.size(), -1);
  std::vector<PortalGeometry> portals(scene.portals.size());
  for (std::size_t p = 0; p < scene.portals.size(); ++p) {
    portals[p].name = scene.portals[p].name;
    for (std::uint32_t m : scene.portals[p].materials) portal_of_material[m] = static_cast<int>(p);
  }
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
    g.areas.push_back(area);
    g.area += area;
    g.centre = g.centre + (a + b + c) * (area / 3.0);
    weighted_normal[static_cast<std::size_t>(p)] = weighted_normal[static_cast<std::size_t>(p)] + face * 0.5;
  }
  for (std::size_t p = 0; p < portals.size(); ++p) {
    PortalGeometry& g = portals[p];
    if (g.triangles.empty() || g.area <= 0) {
      fail_input(scene.file.string() + ": portal \"" + g.name + "\"",
                 "its materials have no triangles with area in the geometry");
    }
    g.centre = g.centre * (1.0 / g.area);
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
        g.diameter = std::max(
            g.diameter, length(mesh.positions[vertices[i]] - mesh.positions[vertices[j]]));
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

}  // namespace relight
