// A portal as the precompute and the run time see it (Yue et al.
// 2009 §3.1): the prepared-mesh triangles of its window materials, its area, the
// area-weighted centre (the centre of the portal's shell), a unit normal and the largest
// distance between two of its points (l in the paper's §6 criterion l/(2r) < θ_M), and its
// outline as convex pieces (sources/portals/portal_outline.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "sources/portals/portal_outline.h"

namespace relight {

struct PortalGeometry {
  std::string name;
  std::vector<std::uint32_t> triangles;  // prepared-mesh triangle ids
  std::vector<PortalPiece> pieces;       // convex planar pieces, their union the triangles'
  double area = 0;                       // m²
  Vec3 centre;                           // area-weighted centroid
  Vec3 normal;          // unit, area-weighted geometric normal (front side); (0,0,0) if they cancel
  double diameter = 0;  // m, largest distance between two vertices
};

// One entry per scene portal, in scene order. InputError (naming the portal) when a portal's
// materials own no triangle.
std::vector<PortalGeometry> portal_geometry(const Scene& scene, const PreparedMesh& mesh);

// Per prepared-mesh vertex: 1 when every triangle using it is a portal triangle (glass
// receives no light of its own; its transfer is left empty).
std::vector<std::uint8_t> portal_vertices(const PreparedMesh& mesh,
                                          const std::vector<Material>& materials);

// The paper's §6 criterion: with the exterior no nearer than `distance` (m) to the portal,
// every point of the portal sees an exterior point within l/(2r) of the direction the shell
// gives it (radians). The largest portal size for a tolerance θ_M is 2·r·θ_M.
double shell_direction_error(double diameter, double distance);

// Distance from `point` to the nearest triangle of the scene's exterior geometry (infinity
// when there is none).
double nearest_exterior_distance(Vec3 point, const std::vector<ExteriorGeometry>& exterior);

// The §6 check of every portal: one message per portal whose shell assumption breaks for
// the nearest exterior object — the portal's "exterior_distance" when given, else the
// nearest exterior geometry of the scene; portals that see only sky are never flagged.
std::vector<std::string> shell_size_warnings(const Scene& scene,
                                             const std::vector<PortalGeometry>& portals);

}  // namespace relight
