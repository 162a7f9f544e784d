// A calculation grid over a floor (EN 12464-1 §4.3 and its area layout): points on a square
// lattice of the given spacing, centred on the floor's extent, inside the floor's outline (the
// union of its triangles seen from above) and at least `border` from that outline, the band that
// EN 12464-1 keeps free of the task area (0.5 m by default), all at one height. Pinned by
// tests/import/floor_grid_test.cpp (a room's count and border; an L-shaped room whose two parts
// meet at a T-junction).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

// `footprint`: the floor's triangles (only x and z are read); points at y = `height`.
std::vector<Vec3> floor_grid(std::span<const std::array<Vec3, 3>> footprint, double height,
                             double spacing, double border);

}  // namespace relight
