#include "scene/scene.h"

namespace relight {

Bounds Scene::bounds() const {
  if (geometry.positions.empty()) return mesh_bounds.value_or(Bounds{});
  Bounds b{geometry.positions.front(), geometry.positions.front()};
  for (const Vec3& p : geometry.positions) {
    b.min = min(b.min, p);
    b.max = max(b.max, p);
  }
  return b;
}

std::size_t Scene::sensor_count() const {
  std::size_t n = 0;
  for (const SensorSet& s : sensors) n += s.points.size();
  return n;
}

std::vector<int> Scene::portal_of_material() const {
  std::vector<int> portal(materials.size(), -1);
  for (std::size_t p = 0; p < portals.size(); ++p) {
    for (std::uint32_t m : portals[p].materials) portal.at(m) = static_cast<int>(p);
  }
  return portal;
}

const Camera* Scene::find_camera(const std::string& name) const {
  for (const Camera& c : cameras) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace relight
