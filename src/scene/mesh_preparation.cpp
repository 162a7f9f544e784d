// The mesh preparation pipeline (weld, subdivide, per-vertex attributes):
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
  if (!soup.textures.empty() && (soup.textures.triangle_texture.size() != soup.triangles.size() ||
                                 soup.textures.corner_uv.size() != 3 * soup.triangles.size())) {
    throw std::invalid_argument("prepare_mesh: textures for another number of triangles");
  }
  for (const std::int32_t k : soup.textures.triangle_texture) {
    if (k >= static_cast<std::int32_t>(soup.textures.textures.size()) ||
        (k >= 0 && !soup.textures.textures[static_cast<std::size_t>(k)])) {
      throw std::invalid_argument("prepare_mesh: texture index out of range");
    }
  }
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
  mesh.triangle_source.resize(soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    mesh.triangle_source[t] = static_cast<std::uint32_t>(t);
  }
  drop_degenerate_triangles(mesh);
  subdivide_long_edges(mesh, settings.max_edge);
  PreparedMesh prepared = split_and_shade(mesh, settings.crease_deg);
  // split_and_shade keeps the triangles in order, so mesh.triangle_source still applies.
  prepared.triangle_textures =
      prepared_triangle_textures(soup.textures, soup.positions, soup.triangles, prepared.positions,
                                 prepared.triangles, mesh.triangle_source);
  prepared.vertex_texture =
      sample_vertex_textures(prepared.triangle_textures, prepared.positions, prepared.triangles);
  return prepared;
}

}  // namespace relight
