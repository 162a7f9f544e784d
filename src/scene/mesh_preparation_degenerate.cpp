// Dropping degenerate triangles after welding: a triangle with a repeated vertex or with
// (numerically) no area has no normal, would give its vertices a meaningless one, and
// receives no light. "No area" is relative: twice the area below kFlatness times the squared
// longest edge, i.e. a height under about 1e-10 of the triangle's length.
#include <algorithm>

#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

constexpr double kFlatness = 1e-10;

bool degenerate(const std::vector<Vec3>& positions, const Triangle& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return true;
  const Vec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
  const double twice_area = length(cross(b - a, c - a));
  const double longest2 = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  return !(twice_area > kFlatness * longest2);
}

}  // namespace

void drop_degenerate_triangles(IndexedMesh& mesh) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (degenerate(mesh.positions, mesh.triangles[i])) continue;
    mesh.triangles[kept] = mesh.triangles[i];
    mesh.triangle_material[kept] = mesh.triangle_material[i];
    mesh.triangle_source[kept] = mesh.triangle_source[i];
    ++kept;
  }
  mesh.triangles.resize(kept);
  mesh.triangle_material.resize(kept);
  mesh.triangle_source.resize(kept);
}

}  // namespace relight
