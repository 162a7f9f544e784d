// Rotation of real SH coefficient vectors (conventions of math/sh.h, no Condon–Shortley phase).
//
// Per-band rotation matrices by the recursion of Ivanic & Ruedenberg, "Rotation Matrices for
// Real Spherical Harmonics. Direct Determination by Recursion", J. Phys. Chem. 100 (1996)
// 6342–6347, in its corrected form (Additions and Corrections, J. Phys. Chem. A 102 (1998)
// 9099), as also used by google/spherical-harmonics: M^l_mn = u U + v V + w W with
//   u = sqrt((l+m)(l−m)/D), v = ½ sqrt((1+δ_m0)(l+|m|−1)(l+|m|)/D)(1−2δ_m0),
//   w = −½ sqrt((l−|m|−1)(l−|m|)/D)(1−δ_m0),  D = 2l(2l−1) if |n| = l else (l+n)(l−n),
// and U, V, W from the helper P^l_{i,a,b} of Table 2, where the m = ±1 cases of V carry the
// sqrt(1+δ_{|m|,1}) and (1−δ_{|m|,1}) factors. Band 1 is the rotation matrix itself in the
// (y, z, x) order of (Y_1,−1, Y_10, Y_11); band l is built from band l−1 and band 1, so the
// whole set costs O(order⁴) once. Checked in tests/math/sh_rotation_test.cpp against
// projection of the rotated function (rounding-level agreement up to order 16; matrices
// orthogonal to 1e-10 and agreement to 1e-9 at order 32).
//
// Meaning: with R a rotation of directions, the ShRotation built from R maps the coefficients
// of f to those of the rotated function g(d) = f(Rᵀ d) (a lobe along a ends up along R a).
// Built from a Frame (R = [t b n]), it maps coefficients expressed in the frame's local
// coordinates to world coordinates: this is how a luminaire projected once in its own frame is
// aimed, by rotation rather than a new projection.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "math/frame.h"
#include "math/mat3.h"
#include "math/rgb.h"
#include "math/sh.h"

namespace relight {

struct ShRotation {
  int order = 0;
  // Band l's (2l+1)×(2l+1) matrix M_l, row-major, rows m and columns n from −l to l, starts
  // at band_offset(l): out_lm = Σ_n M_l(m, n) in_ln.
  std::vector<double> matrices;

  static constexpr std::size_t band_offset(int l) {
    return static_cast<std::size_t>(l) * (4 * l * l - 1) / 3;  // Σ_{k<l} (2k+1)²
  }
  double element(int l, int m, int n) const {
    return matrices[band_offset(l) + static_cast<std::size_t>(m + l) * (2 * l + 1) + (n + l)];
  }
};

// Rotation matrices for bands l < order. `r` must be a proper rotation (orthonormal, det +1).
ShRotation make_sh_rotation(int order, const Mat3& r);
// Local → world of the frame (r = [t b n]).
ShRotation make_sh_rotation(int order, const Frame& local_to_world);

// out = rotation applied to in. Both hold n² values for some n <= rot.order (the first n
// bands are rotated); they must not overlap. No allocation.
void sh_rotate(const ShRotation& rot, std::span<const double> in, std::span<double> out);
void sh_rotate(const ShRotation& rot, std::span<const Rgb> in, std::span<Rgb> out);
// Several vectors stored back to back: in.size() == out.size() == count · rot.order².
void sh_rotate_batch(const ShRotation& rot, std::span<const double> in, std::span<double> out);

}  // namespace relight
