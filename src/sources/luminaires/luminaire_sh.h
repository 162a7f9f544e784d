// Run-time spherical-harmonic weights of a luminaire: the world-frame SH coefficients w_lm of
// its intensity distribution I(ω) (candela, ω = unit direction FROM the luminaire, world
// frame), which weight the precomputed responses to the basis distributions Y_lm(ω).
//
// Dobashi, Kaneda, Nakatani, Yamashita, Nishita, "A Quick Rendering Method Using Basis
// Functions for Interactive Lighting Design", CGF 1995 (Dobashi et al. 1995); a distribution is
// projected once in its own frame and aimed by rotation, not recomputation:
//  * Axisymmetric distributions (isotropic, cosine power, curve, webs whose C planes are all
//    equal): Legendre weights w_l of Eq. 2-3 by composite Simpson (Eq. 19), windowed per band
//    (Eq. 12-13 sigma factor or an alternative of math/sh_window.h), aimed by the addition
//    theorem (Eq. 7-10: w_lm = 4π/(2l+1) σ_l w_l Y_lm(aim), math/zonal.h zonal_rotate).
//    Eq. 19 is applied on the *support pieces* of I, not on one uniform grid over [0, π]: a
//    piece ends wherever I has a jump or a kink (the cut-off of a cosine-power spot, the
//    control points of a curve, the γ angles of a web), each piece gets an even number of
//    intervals (≈ simpson_intervals per π, at least 2), so the integrand is smooth on every
//    Simpson panel and the rule keeps its h⁴ accuracy. On one uniform grid a hard cut-off is
//    an O(h) error, measured on math/zonal.h legendre_weights (worst over cut-off positions):
//    a cos^50 spot cut at 20° needs M ≈ 2048 intervals for 0.1 % flux, a cos^1 cone cut at
//    20° M ≈ 16384, a 5° cone more. With the default 1024 intervals per π of support the
//    flux (l = 0) of a cos^50 spot cut at 20° is exact to ~4e-9 relative, and to ~1e-7 for
//    every exponent 0..200 with cut-offs 5..120° (tests/sources/luminaires/luminaire_sh_test.cpp).
//    The interactive curve editor (Eq. 21) keeps the paper's uniform grid instead:
//    sources/luminaires/luminaire_sh_curve.h.
//  * Webs with C dependence: the bilinear web is projected onto all order² SH in the
//    luminaire's own right-handed frame (sources/luminaires/luminaire_sh_web.h: exact in C,
//    per-cell Gauss–Legendre in γ), windowed, and aimed by a general SH rotation
//    (math/sh_rotation.h).
//
// Handedness. The photometric frame (x = c0, y = c90 = cross(c0, aim), z = aim) of
// light/distribution.h is LEFT-handed (cross(c0, c90) = −aim), so local → world is an improper
// orthogonal map that no SH rotation represents. We project in the right-handed frame
// (t = c0, b = cross(aim, c0) = −c90, n = aim), where the distribution reads I(x', −y', z'):
// its coefficients are those of I in photometric coordinates with every m < 0 (sin mC)
// coefficient negated. The proper rotation [t b n] then aims them.
#pragma once

#include <span>
#include <vector>

#include "light/distribution.h"
#include "math/frame.h"
#include "math/sh_window.h"
#include "math/vec3.h"

namespace relight {

// Which projection luminaire_world_sh takes.
enum class LuminaireShPath {
  kAuto,      // kLegendre when Distribution::axisymmetric(), else kFull
  kLegendre,  // Eq. 3 + addition theorem; std::invalid_argument for a non-axisymmetric web
  kFull,      // full SH projection + general rotation (any distribution; analytic models are
              // projected as their Legendre series, which is their exact SH projection)
};

struct LuminaireShSettings {
  int order = 8;                       // bands l < order; order² coefficients
  ShWindow window = ShWindow::kSigma;  // per-band window against Gibbs ringing (Eq. 12-13)
  double window_param = 0.0;           // λ of kGaussian / kLaplacian
  int simpson_intervals = 1024;        // Eq. 19 density: Simpson intervals per π of support
  LuminaireShPath path = LuminaireShPath::kAuto;
};

// A distribution projected once in its own right-handed frame (t = c0, b = aim × c0, n = aim)
// and windowed; aiming it is a rotation only.
struct LocalLuminaireSh {
  int order = 0;
  bool zonal = false;          // axisymmetric about the aim axis
  std::vector<double> coeffs;  // zonal: z_l, l < order; else order² SH coefficients
};

// The right-handed luminaire frame: t = c0 made orthogonal to aim, b = cross(aim, t) (= −c90),
// n = aim. aim must be non-zero (it is normalised); a c0 parallel to aim falls back to any
// perpendicular (frame_from_normal_and_hint).
Frame luminaire_sh_frame(Vec3 aim, Vec3 c0);

// Eq. 3 by composite Simpson on the support pieces (see above): w_0 .. w_{order−1} in candela,
// I(γ) ≈ Σ w_l P_l(cosγ). Isotropic is exact (w_0 = I). Unwindowed. Throws
// std::invalid_argument for a non-axisymmetric distribution or order < 1.
std::vector<double> distribution_legendre_weights(const Distribution& distribution, int order,
                                                  int simpson_intervals = 1024);

// Projection in the luminaire frame, windowed (settings.window). Throws std::invalid_argument
// for order < 1 or a forced kLegendre path on a non-axisymmetric distribution.
LocalLuminaireSh project_luminaire_local(const Distribution& distribution,
                                         const LuminaireShSettings& settings = {});

// World-frame coefficients (local.order² values into world) for the given aim and C0
// direction (c0 is ignored for zonal projections). Zonal: no allocation.
void aim_luminaire_sh(const LocalLuminaireSh& local, Vec3 aim, Vec3 c0, std::span<double> world);
std::vector<double> aim_luminaire_sh(const LocalLuminaireSh& local, Vec3 aim, Vec3 c0);

// Both steps: settings.order² world-frame coefficients of I(ω) in candela.
std::vector<double> luminaire_world_sh(const Distribution& distribution, Vec3 aim, Vec3 c0,
                                       const LuminaireShSettings& settings = {});

// ∫ I dω (lumens) of an SH series: sqrt(4π) · w_00. Windows keep band 0, so this is the
// projected distribution's flux.
double sh_flux_lm(std::span<const double> world_sh);

}  // namespace relight
