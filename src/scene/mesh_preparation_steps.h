// The steps of mesh preparation (mesh_preparation.h), each in its own file so each can be
// read and tested on its own. Internal to the scene stage.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "scene/mesh_preparation.h"
#include "scene/triangle_soup.h"

namespace relight {

// Indexed triangles with one material each, and the soup triangle each lies in: the state
// passed from step to step.
struct IndexedMesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> triangle_material;
  std::vector<std::uint32_t> triangle_source;
};

// One representative per cluster of positions within `epsilon` (grid hashing; epsilon <= 0
// merges bit-identical positions only). remap[i] is the representative of positions[i].
struct WeldResult {
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> remap;
};
WeldResult weld_positions(std::span<const Vec3> positions, double epsilon);

// Drops triangles with a repeated vertex or (numerically) zero area, in place.
void drop_degenerate_triangles(IndexedMesh& mesh);

// Bisects longest edges until none exceeds max_edge, conformingly (edges split through a
// shared edge -> midpoint map). No-op for max_edge <= 0.
void subdivide_long_edges(IndexedMesh& mesh, double max_edge);

// Smooth normals with vertices split at creases and material boundaries.
PreparedMesh split_and_shade(const IndexedMesh& mesh, double crease_deg);

}  // namespace relight
