#include "engine/receivers.h"

#include <algorithm>
#include <cmath>

#include "material/material_reflectance.h"

namespace relight {

Receivers make_receivers(const Scene& scene, const PreparedMesh& mesh) {
  Receivers r;
  r.vertex_count = mesh.positions.size();
  r.sensor_count = scene.sensor_count();
  r.positions = mesh.positions;
  r.normals = mesh.normals;
  r.albedo.reserve(r.vertex_count + r.sensor_count);
  for (std::size_t v = 0; v < mesh.vertex_material.size(); ++v) {
    r.albedo.push_back(bounce_albedo(scene.materials.at(mesh.vertex_material[v]),
                                     vertex_texture_at(mesh.vertex_texture, v)));
  }
  for (const SensorSet& s : scene.sensors) {
    for (const Vec3& p : s.points) {
      r.positions.push_back(p);
      r.normals.push_back(s.normal);
      r.albedo.push_back({});
    }
  }
  return r;
}

std::vector<Vec3> receiver_ray_points(const Receivers& receivers, const PreparedMesh& mesh) {
  std::vector<Vec3> centroid_sum(receivers.vertex_count);
  std::vector<std::uint32_t> triangles_at(receivers.vertex_count, 0);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 centroid = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3;
    for (std::uint32_t v : t) {
      centroid_sum[v] += centroid;
      ++triangles_at[v];
    }
  }
  std::vector<Vec3> points(receivers.positions);
  for (std::size_t r = 0; r < receivers.vertex_count; ++r) {
    if (triangles_at[r] == 0) continue;
    const Vec3 p = points[r], n = receivers.normals[r];
    const Vec3 toward = centroid_sum[r] / triangles_at[r] - p;
    const Vec3 tangent = toward - n * dot(toward, n);
    const double distance = length(tangent);
    const double scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0});
    const double step = std::min(1e-4 * scale, 0.25 * distance);
    if (step > 0) points[r] = p + tangent * (step / distance);
  }
  return points;
}

}  // namespace relight
