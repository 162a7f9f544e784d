// The texels of a cubemap (math/cubemap.h) that a convex polygon covers, seen from the cube's
// centre: the cells a window covers seen from a receiver (sources/portals/portal_direct.h),
// found without sampling the window. The polygon — its vertices relative to the centre, in
// order around it, planar and convex, its plane not through the centre — is clipped to the
// half-space d · front > 0 and to each face's pyramid (Sutherland & Hodgman 1974), projected
// onto the face (the gnomonic projection maps the polygon's edges, arcs of great circles, to
// straight lines, so the clipped polygon stays convex on the face) and rasterised
// conservatively row by row. Every texel holding a direction through the clipped polygon is
// listed, once; a texel whose edge the outline only touches (within 1e-7 of a texel) may be
// too. Pinned by tests/math/cubemap_polygon_test.cpp (every direction through random
// polygons lands in a listed texel; every listed texel is within reach of one).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

struct CubemapPolygonScratch {
  std::vector<Vec3> in_front, a, b;
  std::vector<double> x, y;
};

// Appends the texels' indices (cubemap_texel_index) to `texels`, face by face, row by row.
void cubemap_polygon_texels(int n, std::span<const Vec3> polygon, Vec3 front,
                            CubemapPolygonScratch& scratch, std::vector<std::uint32_t>& texels);

}  // namespace relight
