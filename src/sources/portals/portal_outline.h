// A portal as a few convex planar pieces whose union is exactly its triangles: what the
// direct transfer (sources/portals/portal_direct.h) needs to find the cubemap cells a window
// covers seen from a receiver (math/cubemap_polygon.h) and whether a direction passes through
// it, without visiting every triangle `max_edge` cut the window into (a 2.4 × 1.5 m window at
// 4 cm is ~4,500 triangles; it is one quadrilateral here).
//
// The portal's triangles are grouped by plane (normals within 1e-6 of each other, offsets
// within 1e-6 m) and, within a plane, by shared vertices. A group whose convex hull (Andrew
// 1979's monotone chain, in the plane) has the group's area within 1e-6 is one piece, its
// hull without collinear vertices; the triangles of any other group (an L-shaped or curved
// window) are pieces each. Pinned by tests/sources/portals/portal_outline_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "scene/mesh_preparation.h"

namespace relight {

// One convex planar piece: its vertices in order around it.
using PortalPiece = std::vector<Vec3>;

std::vector<PortalPiece> portal_pieces(const PreparedMesh& mesh,
                                       std::span<const std::uint32_t> triangles);

// Whether rays from one origin pass through a set of pieces: each piece's edges as planes
// through the origin (a direction is in a piece's cone when it is on the inner side of every
// one). Built per origin; no rays.
class PieceCones {
 public:
  // Pieces whose plane passes within 1e-9 m of the origin (seen edge-on) are left out.
  void reset(Vec3 origin, const std::vector<PortalPiece>& pieces);
  bool contains(Vec3 direction) const;
  std::size_t edges() const { return planes_.size(); }

 private:
  std::vector<Vec3> planes_;         // every piece's edge planes, inner side positive
  std::vector<std::uint32_t> ends_;  // one past each piece's last plane
};

}  // namespace relight
