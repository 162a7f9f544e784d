#include "transfer/receivers.h"

namespace relight {

Receivers make_receivers(const Scene& scene, const PreparedMesh& mesh) {
  Receivers r;
  r.vertex_count = mesh.positions.size();
  r.sensor_count = scene.sensor_count();
  r.positions = mesh.positions;
  r.normals = mesh.normals;
  r.albedo.reserve(r.vertex_count + r.sensor_count);
  for (std::uint32_t m : mesh.vertex_material) {
    const Material& material = scene.materials.at(m);
    r.albedo.push_back(material.portal ? Rgb{} : material.albedo);
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

}  // namespace relight
