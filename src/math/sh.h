// Real orthonormal spherical harmonics (SH): evaluation, projection, reconstruction.
//
// Conventions (every SH function in relight follows them):
//  * `order` = number of bands; coefficients for bands l < order; count order²;
//    index(l, m) = l(l+1) + m, −l <= m <= l.
//  * Direction: a unit Vec3 in whatever frame the caller uses; z is the polar axis
//    (θ from +z) and φ = atan2(y, x) (from +x toward +y), as in Dobashi et al. 1995
//    (Dobashi et al. 1995, Eq. 5-6). Coefficients live in the same frame as the directions.
//  * Real SH WITHOUT the Condon–Shortley phase, orthonormal over the unit sphere:
//      Y_l0  = Pbar_l^0(cosθ)
//      Y_lm  = sqrt(2) Pbar_l^m(cosθ) cos(mφ)     m > 0
//      Y_l−m = sqrt(2) Pbar_l^m(cosθ) sin(mφ)     m > 0
//    with Pbar from math/legendre.h (P_l^m = (1−x²)^{m/2} d^m P_l/dx^m, no (−1)^m). Band 1 is
//    (Y_1,−1, Y_10, Y_11) = sqrt(3/4π) (y, z, x), all with a + sign. This is the phase that
//    the Ivanic–Ruedenberg rotation recursion assumes (math/sh_rotation.h). The paper's
//    Appendix Eq. 22 has a (−1)^m factor; the addition theorem (its Eq. 7) holds in both.
//  * Evaluation is done directly from (x, y, z): Pbar_l^m(cosθ)·(cos mφ, sin mφ) =
//    (Pbar_l^m / sin^mθ)·(Re, Im)(x + iy)^m, so there is no atan2 and no pole singularity
//    (Sloan, "Efficient Spherical Harmonic Evaluation", JCGT 2(2), 2013, §2). Stable and
//    accurate far beyond l = 31.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

constexpr int sh_count(int order) {
  return order * order;
}
constexpr int sh_index(int l, int m) {
  return l * (l + 1) + m;
}
// Order of a coefficient vector of the given length (asserts a perfect square).
int sh_order_from_count(std::size_t count);

// All Y_lm(dir), l < order, into out[0 .. order²) (out.size() >= order²). No allocation.
void sh_eval(int order, Vec3 dir, std::span<double> out);

// Σ c_lm Y_lm(dir): reconstruct a coefficient vector (order from its length) at dir.
// No allocation.
double sh_evaluate(std::span<const double> coeffs, Vec3 dir);
Rgb sh_evaluate(std::span<const Rgb> coeffs, Vec3 dir);

// coeffs[lm] += value · Y_lm(dir): one sample of a projection sum (value already carries
// its quadrature weight / solid angle). No allocation.
void sh_add_sample(Vec3 dir, double value, std::span<double> coeffs);
void sh_add_sample(Vec3 dir, Rgb value, std::span<Rgb> coeffs);

// Product quadrature on the sphere: Gauss–Legendre in cosθ (n_theta nodes) × uniform φ
// (n_phi nodes, φ_k = 2π(k + ½)/n_phi). Exact for spherical polynomials of degree
// <= min(2 n_theta − 1, n_phi − 1). Weights sum to 4π.
struct SphereQuadrature {
  std::vector<Vec3> directions;
  std::vector<double> weights;
};
SphereQuadrature sphere_quadrature(int n_theta, int n_phi);
// The smallest such rule exact to the given polynomial degree: n_theta = degree/2 + 1,
// n_phi = degree + 1.
SphereQuadrature sphere_quadrature_exact_to_degree(int degree);

// c_lm = ∫ f Y_lm dω for l < order by quadrature. Without a rule, the one exact to degree
// (order − 1) + (f_order − 1) is used: the projection is then exact whenever f is band-limited
// to f_order bands (f_order = 0 means f_order = order). Pass a finer rule to reduce aliasing
// of functions that are not band-limited.
std::vector<double> sh_project(int order, const std::function<double(Vec3)>& f, int f_order = 0);
std::vector<double> sh_project(int order, const std::function<double(Vec3)>& f,
                               const SphereQuadrature& rule);
std::vector<Rgb> sh_project_rgb(int order, const std::function<Rgb(Vec3)>& f,
                                const SphereQuadrature& rule);

}  // namespace relight
