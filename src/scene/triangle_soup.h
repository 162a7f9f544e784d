// Triangles as they come from the scene file, before mesh preparation: world-space
// positions, index triples, one material index per triangle (into Scene::materials) and the
// base colour textures of those a glTF file gives one (scene/surface_texture.h).
// Mesh preparation (mesh_preparation.h) turns this into the per-vertex receivers of
// precomputed transfer.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math/placement.h"
#include "math/vec3.h"
#include "scene/surface_texture.h"
#include "scene/triangle.h"

namespace relight {

struct TriangleSoup {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> triangle_material;  // one per triangle
  TriangleTextures textures;                     // empty when no triangle has a texture

  // Appends `other`, offsetting its indices.
  void append(const TriangleSoup& other);
};

// The soup as a lighting state places a rigid object (math/placement.h).
TriangleSoup placed_geometry(const TriangleSoup& soup, Vec3 pivot, const Placement& placement);

}  // namespace relight
