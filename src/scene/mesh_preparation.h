// Mesh preparation: turns the scene's triangle soup into the vertices that receive precomputed
// transfer (receivers are vertices and sensors). Transfer is stored and interpolated per vertex, so
// vertices must be shared where the surface is continuous (welding), close enough together to
// resolve lighting (subdivision to a maximum edge length, without T-junctions), and carry one
// normal and one material each (split at creases and material boundaries).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle_soup.h"

namespace relight {

// Subdivision refuses to produce more triangles than this (2^28, some 10 GB of transfer).
inline constexpr std::size_t kMaxPreparedTriangles = std::size_t{1} << 28;

struct PreparationSettings {
  double max_edge = 0;         // metres; edges are split until none is longer; <= 0: no splits
  double crease_deg = 30;      // neighbouring faces whose normals differ more are not smoothed
  double weld_epsilon = 1e-6;  // metres; positions this close become one; <= 0: exact match only
};

struct PreparedMesh {
  std::vector<Vec3> positions, normals;          // per vertex; normals unit length
  std::vector<std::uint32_t> vertex_material;    // per vertex, into the soup's materials
  std::vector<Triangle> triangles;               // input winding kept
  std::vector<std::uint32_t> triangle_material;  // per triangle, equal to its vertices'
  // The base colour textures (scene/surface_texture.h): per triangle, the soup triangle's with
  // its corners' UVs; per vertex, their mean over its footprint, which multiplies its
  // material's base colour. Both empty when the soup has no textures.
  TriangleTextures triangle_textures;
  std::vector<Rgb> vertex_texture;
};

// Welds, drops degenerate triangles, subdivides and computes crease-aware smooth normals.
// Every output triangle lies inside an input triangle with the same orientation, and its
// vertex normals are on its front side. Throws std::invalid_argument for a malformed soup
// (index out of range, non-finite position, material count mismatch) and InputError when
// max_edge would create more than kMaxPreparedTriangles triangles.
PreparedMesh prepare_mesh(const TriangleSoup& soup, const PreparationSettings& settings);

}  // namespace relight
