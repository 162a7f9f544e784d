#include "scene/triangle_soup.h"

namespace relight {

void TriangleSoup::append(const TriangleSoup& other) {
  const auto offset = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (const Triangle& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  triangle_material.insert(triangle_material.end(), other.triangle_material.begin(),
                           other.triangle_material.end());
}

}  // namespace relight
