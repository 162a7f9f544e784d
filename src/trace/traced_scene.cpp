#include "trace/traced_scene.h"

namespace relight {

TracedScene build_traced_scene(const PreparedMesh& mesh, const std::vector<Material>& materials) {
  std::vector<Triangle> opaque, portal;
  std::vector<std::uint32_t> opaque_ids, portal_ids;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const bool is_portal = materials.at(mesh.triangle_material[t]).portal;
    (is_portal ? portal : opaque).push_back(mesh.triangles[t]);
    (is_portal ? portal_ids : opaque_ids).push_back(t);
  }
  return {RayTracer(mesh.positions, opaque, opaque_ids),
          RayTracer(mesh.positions, portal, portal_ids)};
}

Vec3 geometric_normal(const PreparedMesh& mesh, std::uint32_t triangle) {
  const Triangle& t = mesh.triangles[triangle];
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  return normalize(cross(b - a, c - a));
}

Vec3 point_on_triangle(const PreparedMesh& mesh, std::uint32_t triangle, double u, double v) {
  const Triangle& t = mesh.triangles[triangle];
  return mesh.positions[t[0]] * (1 - u - v) + mesh.positions[t[1]] * u + mesh.positions[t[2]] * v;
}

PreparedMesh prepare_scene_mesh(const Scene& scene) {
  PreparationSettings settings;
  settings.max_edge = scene.precompute.max_edge;
  settings.crease_deg = scene.precompute.crease_deg;
  return prepare_mesh(scene.geometry, settings);
}

}  // namespace relight
