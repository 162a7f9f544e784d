#include "scene/triangle_soup.h"

namespace relight {

void TriangleSoup::append(const TriangleSoup& other) {
  textures.append(other.textures, triangles.size(), other.triangles.size());
  const auto offset = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (const Triangle& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  triangle_material.insert(triangle_material.end(), other.triangle_material.begin(),
                           other.triangle_material.end());
}

TriangleSoup placed_geometry(const TriangleSoup& soup, Vec3 pivot, const Placement& placement) {
  TriangleSoup out = soup;
  for (Vec3& p : out.positions) p = placed_point(p, pivot, placement);
  return out;
}

}  // namespace relight
