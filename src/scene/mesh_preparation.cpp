// The mesh preparation pipeline (ARCHITECTURE §2: weld, subdivide, per-vertex attributes):
// weld -> drop degenerate -> subdivide -> normals and vertex splitting. Order matters:
// welding first lets subdivision share midpoints across what were separate soup triangles,
// and normals come last so that they see the final vertices.
#include "scene/mesh_preparation.h"

#include <stdexcept>
#include <string>

#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

void check_soup(const TriangleSoup& soup) {
  if (soup.triangle_material.size() != soup.triangles.size()) {
    throw std::invalid_argument("prepare_mesh: " + std::to_string(soup.triangles.size()) +
                                " triangles but " + std::to_string(soup.triangle_material.size()) +
                                " materials");
  }
  for (const Vec3& p : soup.positions) {
    if (!is_finite(p)) throw std::invalid_argument("prepare_mesh: non-finite position");
  }
  for (const Triangle& t : soup.triangles) {
    for (const std::uint32_t i : t) {
      if (i >= soup.positions.size()) {
        throw std::invalid_argument("prepare_mesh: vertex index " + std::to_string(i) +
                                    " out of range");
      }
    }
  }
}

}  // namespace

PreparedMesh prepare_mesh(const TriangleSoup& soup, const PreparationSettings& settings) {
  check_soup(soup);
  WeldResult welded = weld_positions(soup.positions, settings.weld_epsilon);
  IndexedMesh mesh;
  mesh.positions = std::move(welded.positions);
  mesh.triangles.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) {
    mesh.triangles.push_back({welded.remap[t[0]], welded.remap[t[1]], welded.remap[t[2]]});
  }
  mesh.triangle_material = soup.triangle_material;
  drop_degenerate_triangles(mesh);
  subdivide_long_edges(mesh, settings.max_edge);
  return split_and_shade(mesh, settings.crease_deg);
}

}  // namespace relight
