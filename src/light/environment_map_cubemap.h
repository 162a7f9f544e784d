// Exact cubemap texel averages of a piecewise-constant equirectangular map.
//
// In the map's equal-area coordinates (φ, z = cos θ) the solid angle is dω = dφ dz and every
// map texel is a rectangle [φ_i, φ_i+1] × [cos θ_j+1, cos θ_j] of constant value f_ij. For a
// region R (a cube texel seen in these coordinates) Green's theorem gives
//     ∫_R f dω = ∬_R ∂G/∂φ dφ dz = ∮_∂R G dz,   G(φ, z) = ∫_0^φ f(φ', z) dφ',
// where G is, within a map row, the prefix sum of the row up to column i plus f_ij (φ − φ_i):
// continuous and piecewise linear in φ, periodic up to the row total T(z) = G(2π, z). Each cube
// texel edge is a great-circle arc; it is split where it crosses map rows (z = cos θ_j, a
// quadratic in the segment parameter) and columns (φ = φ_i, linear), and on each piece the
// integral is the prefix times Δz plus f_ij ∫ (φ − φ_i) dz, the latter by 3-point
// Gauss–Legendre on a smooth integrand (pieces at most 1° long and 1° wide in φ). φ is unwrapped
// along the loop; the texel that contains a pole (the centre of the ±Y faces for odd N) winds once
// around it, and is closed along the pole line (z = ±1, where dz = 0) with the term ±∫_{z0}^{±1}
// T(z) dz. The loop orientation is taken from the same integral with f ≡ 1 (the texel's solid
// angle, checked in the tests against the exact formula of math/cubemap.h).
//
// Hence a constant map gives a constant cubemap, and Σ_texels L·Ω equals Σ_map L·Ω up to
// rounding (every interior edge is integrated once in each direction).
#pragma once

#include <vector>

#include "light/environment.h"
#include "math/rgb.h"

namespace relight {

// 6·N² average radiances (math/cubemap.h layout) of the map turned by rotate_deg (clockwise
// seen from above, as Environment) and multiplied by scale.
std::vector<Rgb> equirect_map_to_cubemap(const EquirectMap& map, double rotate_deg, double scale,
                                         int face_size);

// The same integral with f ≡ 1: the solid angle of cube texel (face, i, j) as this method
// computes it (for tests; equals cubemap_texel_solid_angle to ~1e-12).
double equirect_raster_texel_solid_angle(int map_width, int map_height, int face_size, int face,
                                         int i, int j);

}  // namespace relight
