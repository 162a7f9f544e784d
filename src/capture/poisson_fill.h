// Seamless filling of an equirectangular map's holes (what no view saw and what was removed;
// capture/capture.h). Pérez, Gangnet & Blake, "Poisson Image Editing" (SIGGRAPH 2003), Eq. 2 with a
// zero guidance field: inside the hole the Laplacian of the fill is zero and on its border it meets
// the map, i.e. the smoothest membrane over the hole. It is solved in float, per channel, on the
// linear values: the membrane is a weighted mean of the border, so a hole over a striped rug gets
// the rug's mean luminance (a membrane in ln gets the geometric mean, 25 % too dark on a synthetic
// capture). 5-point Laplacian, the map's columns wrapping around (u = 0 meets u = 1), no neighbour
// beyond the poles; one sparse Cholesky factorisation (Eigen SimplicialLDLT) serves the three
// channels.
// Pinned by tests/capture/poisson_fill_test.cpp.
#pragma once

#include <cstdint>
#include <span>

#include "math/rgb.h"

namespace relight {

// Replaces the texels with hole[t] != 0 of a width × height map (row-major). Throws
// std::invalid_argument when every texel is a hole.
void poisson_fill(int width, int height, std::span<Rgb> texels, std::span<const std::uint8_t> hole);

}  // namespace relight
