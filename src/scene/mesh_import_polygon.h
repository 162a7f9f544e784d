// Splitting one polygon face of a mesh file (OBJ, PLY) into triangles that keep the
// polygon's winding, so that front faces stay front faces through import.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "scene/triangle_soup.h"

namespace relight {

// Appends triangles covering the polygon whose corners are `corners` (indices into
// `positions`, all valid) in order. Convex polygons give a fan; concave simple polygons are
// ear-clipped in their best-fit (Newell) plane; whatever cannot be ear-clipped
// (self-intersecting or degenerate corners) is fanned. Fewer than 3 corners append nothing.
void triangulate_polygon(std::span<const std::uint32_t> corners, std::span<const Vec3> positions,
                         std::vector<Triangle>& out);

}  // namespace relight
