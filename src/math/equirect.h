// Equirectangular (latitude–longitude) maps: texel ↔ direction, per-texel solid angles, SH
// projection.
//
// Orientation (world frame: right-handed, y up):
//  * A W×H map; texel (i, j) has column i and row j, flat index j·W + i; row 0 is the first
//    row stored (the top of the image).
//  * u = (i + ½)/W ∈ (0, 1) and v = (j + ½)/H ∈ (0, 1) at texel centres.
//  * θ = π v is the angle from the +y pole: v = 0 is straight up (+y), v = 1 straight down.
//  * φ = 2π u is the azimuth, φ = 0 toward −z, increasing toward +x:
//      d = (sinθ sinφ, cosθ, −sinθ cosφ)
//    so u = 0 → −z, u = ¼ → +x, u = ½ → +z, u = ¾ → −x: read left to right, the panorama
//    turns to the right (clockwise seen from above) for a viewer standing with +y up, so the
//    image is not mirrored.
//  * Row j covers θ ∈ [πj/H, π(j+1)/H], hence each of its texels subtends exactly
//    Ω_j = (2π/W)(cos(πj/H) − cos(π(j+1)/H)); the sum over the map is 4π.
// SH coefficients from sh_project_equirect are in the world frame of the directions (SH polar
// axis = world z, see math/sh.h), regardless of the map's y-up orientation.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

// Unit direction of map coordinates (u, v) ∈ [0, 1]².
Vec3 equirect_direction(double u, double v);
// Map coordinates (u ∈ [0, 1), v ∈ [0, 1]) of a non-zero direction.
struct EquirectUv {
  double u = 0, v = 0;
};
EquirectUv equirect_uv(Vec3 dir);

// Texel centre direction and the texel containing a direction (column i, row j).
Vec3 equirect_texel_direction(int width, int height, int i, int j);
struct EquirectTexel {
  int i = 0, j = 0;
};
EquirectTexel equirect_texel(int width, int height, Vec3 dir);

// Exact solid angle of every texel of row j.
double equirect_row_solid_angle(int width, int height, int j);

// c_lm = Σ_texels value · Y_lm(centre) · Ω_j for l < order; texels hold width·height values
// (index j·W + i). Error O(1/H²) for smooth functions.
std::vector<double> sh_project_equirect(int order, int width, int height,
                                        std::span<const double> texels);
std::vector<Rgb> sh_project_equirect(int order, int width, int height, std::span<const Rgb> texels);

}  // namespace relight
