// Luminaire SH weights (sources/luminaires/luminaire_sh.h): closed forms for the analytic models,
// the flux (l = 0) of Simpson on the support pieces, aiming by rotation with the left-handed
// photometric frame handled, agreement of the Legendre and full paths, and the sigma factor
// of Dobashi et al. 1995 Eq. 13 against Gibbs ringing.
#include "sources/luminaires/luminaire_sh.h"

#include <gtest/gtest.h>

#include "support/sh_compare.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "light/luminaire_frame.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/zonal.h"
#include "sources/luminaires/luminaire_sh_web.h"

namespace relight {
namespace {

using testing::max_abs;
using testing::max_abs_diff;

Vec3 random_unit(Pcg32& rng) {
  const double u = rng.next_double();
  return sample_uniform_sphere(u, rng.next_double());
}

// A unit c0 orthogonal to aim.
Vec3 random_c0(Pcg32& rng, Vec3 aim) {
  return normalize(cross(aim, random_unit(rng)));
}

Distribution cosine_power(double candela, double exponent, double cutoff_deg) {
  return {CosinePowerModel{candela, exponent, radians(cutoff_deg)}};
}

// (2l+1)/2 ∫_0^1 x P_l(x) dx: the Legendre weights of the clamped cosine max(cosγ, 0).
double clamped_cosine_legendre(int l) {
  if (l == 0) return 0.5 * 0.5;
  if (l == 1) return 1.5 / 3.0;
  if (l % 2 == 1) return 0.0;
  // (−1)^{l/2−1} (l−2)! / (2^l (l/2−1)! (l/2+1)!)
  const int h = l / 2;
  const double v =
      std::tgamma(l - 1.0) / (std::pow(2.0, l) * std::tgamma(h) * std::tgamma(h + 2.0));
  return 0.5 * (2 * l + 1) * ((h - 1) % 2 == 0 ? v : -v);
}

// A smooth C-dependent web: I = 1 + 0.5 sinγ cosC + 0.3 sinγ sinC + 0.3 cos²γ
// + 0.2 sin²γ sin2C, sampled every 5° in C and 2.5° in γ. The sinC and sin2C terms are odd
// under C → −C, so a mirrored (left-handed) frame shows.
PhotometricWeb smooth_web(double c_step = 5.0, double g_step = 2.5) {
  std::vector<double> cs, gs, cd;
  for (double c = 0; c < 360 - 1e-9; c += c_step) cs.push_back(c);
  for (double g = 0; g <= 180 + 1e-9; g += g_step) gs.push_back(std::min(g, 180.0));
  for (const double c : cs) {
    for (const double g : gs) {
      const double cr = radians(c), gr = radians(g);
      cd.push_back(1.0 + 0.5 * std::sin(gr) * std::cos(cr) + 0.3 * std::sin(gr) * std::sin(cr) +
                   0.3 * std::cos(gr) * std::cos(gr) +
                   0.2 * std::sin(gr) * std::sin(gr) * std::sin(2 * cr));
    }
  }
  return make_web(cs, gs, cd, CSymmetry::kNone);
}

// An axially symmetric web: 1000 cos³γ on 0..90° (5° steps), zero beyond.
PhotometricWeb axial_web() {
  std::vector<double> gs, cd;
  for (int g = 0; g <= 90; g += 5) {
    gs.push_back(g);
    cd.push_back(1000.0 * std::pow(std::cos(radians(g)), 3));
  }
  return make_web({0.0}, gs, cd, CSymmetry::kAxial);
}

TEST(LuminaireSh, IsotropicHasOnlyBandZero) {
  const Distribution iso{IsotropicModel{250.0}};
  Pcg32 rng(7, 1);
  for (const int order : {1, 8, 16}) {
    const Vec3 aim = random_unit(rng);
    const auto w = luminaire_world_sh(iso, aim, random_c0(rng, aim), {.order = order});
    ASSERT_EQ(w.size(), static_cast<std::size_t>(order * order));
    EXPECT_NEAR(w[0], std::sqrt(4 * kPi) * 250.0, 1e-12 * w[0]);
    for (std::size_t i = 1; i < w.size(); ++i) EXPECT_EQ(w[i], 0.0) << i;
    EXPECT_NEAR(sh_flux_lm(w), iso.flux_lm(), 1e-12 * iso.flux_lm());
  }
}

TEST(LuminaireSh, ClampedCosineMatchesClosedForm) {
  const Distribution cosine = cosine_power(1.0, 1.0, 90.0);
  const int order = 8;
  std::vector<double> zonal(order);
  for (int l = 0; l < order; ++l)
    zonal[l] = std::sqrt(4 * kPi / (2 * l + 1)) * clamped_cosine_legendre(l);
  // The textbook values: z_0 = sqrt(π)/2, z_1 = sqrt(π/3), z_2 = sqrt(5π)/8.
  EXPECT_NEAR(zonal[0], std::sqrt(kPi) / 2, 1e-14);
  EXPECT_NEAR(zonal[1], std::sqrt(kPi / 3), 1e-14);
  EXPECT_NEAR(zonal[2], std::sqrt(5 * kPi) / 8, 1e-14);

  const LuminaireShSettings s{.order = order, .window = ShWindow::kNone};
  const auto up = luminaire_world_sh(cosine, {0, 0, 1}, {1, 0, 0}, s);
  for (int l = 0; l < order; ++l) {
    for (int m = -l; m <= l; ++m) {
      EXPECT_NEAR(up[sh_index(l, m)], m == 0 ? zonal[l] : 0.0, 1e-4) << l << " " << m;
    }
  }
  Pcg32 rng(3, 2);
  for (int trial = 0; trial < 3; ++trial) {
    const Vec3 aim = random_unit(rng);
    const auto w = luminaire_world_sh(cosine, aim, random_c0(rng, aim), s);
    EXPECT_LT(max_abs_diff(w, zonal_rotate(zonal, aim)), 1e-4);
    // Simpson on [0, 90°] is far better than the 1e-4 asked for.
    EXPECT_LT(max_abs_diff(w, zonal_rotate(zonal, aim)), 1e-9);
  }
}

TEST(LuminaireSh, CosinePowerFluxIsExactOnTheSupport) {
  // Simpson on [0, min(cut-off, 90°)]: no O(h) error from the cut-off jump.
  double worst = 0.0;
  std::string worst_case;
  for (const double exponent : {0.0, 1.0, 10.0, 50.0, 200.0}) {
    for (const double cutoff : {5.0, 20.0, 45.0, 60.0, 90.0, 120.0}) {
      const Distribution d = cosine_power(1000.0, exponent, cutoff);
      const auto w = luminaire_world_sh(d, {0, -1, 0}, {1, 0, 0});
      const double err = std::abs(sh_flux_lm(w) / d.flux_lm() - 1.0);
      if (err > worst) {
        worst = err;
        worst_case = "cos^" + std::to_string(exponent) + " cut " + std::to_string(cutoff);
      }
      EXPECT_LT(err, 1e-6) << exponent << " " << cutoff;
    }
  }
  const Distribution spot = cosine_power(1000.0, 50.0, 20.0);
  const double spot_err =
      std::abs(sh_flux_lm(luminaire_world_sh(spot, {0, 0, 1}, {1, 0, 0})) / spot.flux_lm() - 1.0);
  EXPECT_LT(spot_err, 1e-8);
  RecordProperty("cos50_cut20_flux_relative_error", std::to_string(spot_err));
  RecordProperty("worst_flux_relative_error", std::to_string(worst) + " (" + worst_case + ")");
  std::cout << "cos^50 cut 20°: flux relative error " << spot_err << "; worst " << worst << " ("
            << worst_case << ")\n";
}

TEST(LuminaireSh, SimpsonWeightsConvergedAtDefaultDensity) {
  const Distribution spot = cosine_power(1000.0, 50.0, 20.0);
  const auto w = distribution_legendre_weights(spot, 32);
  const auto fine = distribution_legendre_weights(spot, 32, 8192);
  EXPECT_LT(max_abs_diff(w, fine), 1e-6 * max_abs(fine));
  const auto w8 = distribution_legendre_weights(spot, 8);
  const auto fine8 = distribution_legendre_weights(spot, 8, 8192);
  EXPECT_LT(max_abs_diff(w8, fine8), 1e-8 * max_abs(fine8));
}

TEST(LuminaireSh, EveryWindowKeepsTheFlux) {
  const Distribution spot = cosine_power(1000.0, 10.0, 60.0);
  for (const ShWindow window : {ShWindow::kNone, ShWindow::kSigma, ShWindow::kHanning,
                                ShWindow::kGaussian, ShWindow::kLaplacian}) {
    const auto w = luminaire_world_sh(spot, normalize(Vec3{1, -2, 0.5}), {0, 0, 1},
                                      {.order = 8, .window = window, .window_param = 0.01});
    EXPECT_NEAR(sh_flux_lm(w), spot.flux_lm(), 1e-9 * spot.flux_lm());
  }
}

TEST(LuminaireSh, WebAimedByRotationMatchesPlacedLuminaire) {
  const Distribution web{smooth_web()};
  const double peak = web.max_intensity();
  const LuminaireShSettings s{.order = 16, .window = ShWindow::kNone};
  const LocalLuminaireSh local = project_luminaire_local(web, s);
  ASSERT_FALSE(local.zonal);
  Pcg32 rng(11, 5);
  std::vector<std::pair<Vec3, Vec3>> frames = {
      {{0, -1, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {normalize(Vec3{1, -1, 0}), {0, 0, 1}}};
  for (int i = 0; i < 3; ++i) {
    const Vec3 aim = random_unit(rng);
    frames.push_back({aim, random_c0(rng, aim)});
  }
  double worst = 0.0;
  for (const auto& [aim, c0] : frames) {
    const auto w = aim_luminaire_sh(local, aim, c0);
    const PlacedLuminaire placed{{0, 0, 0}, photometric_frame(aim, c0), Rgb{1, 1, 1}, web};
    for (int k = 0; k < 400; ++k) {
      const Vec3 d = random_unit(rng);
      const double exact = placed.distribution.intensity(placed.frame.to_photometric(d));
      worst = std::max(worst, std::abs(sh_evaluate(w, d) - exact) / peak);
    }
    // C90 lies along cross(c0, aim) (I = 1.3 there), C270 opposite (I = 0.7).
    const Vec3 c90 = cross(c0, aim);
    EXPECT_NEAR(sh_evaluate(w, c90), 1.3, 0.01 * peak);
    EXPECT_NEAR(sh_evaluate(w, -c90), 0.7, 0.01 * peak);
    EXPECT_NEAR(sh_evaluate(w, c0), 1.5, 0.01 * peak);
    EXPECT_NEAR(sh_evaluate(w, aim), 1.3, 0.01 * peak);
  }
  EXPECT_LT(worst, 0.01);
  RecordProperty("worst_error_over_peak", std::to_string(worst));
  std::cout << "order-16 web vs PlacedLuminaire: worst |error| / peak = " << worst << "\n";
}

TEST(LuminaireSh, WebProjectionMatchesBruteForceQuadrature) {
  // Independent check of the closed-form C integrals: a fine generic sphere rule applied to
  // the interpolant as Distribution evaluates it, in the right-handed frame (y = −C90).
  const Distribution web{smooth_web(30.0, 15.0)};  // coarse cells: strong kinks
  const int order = 8;
  const auto exact = web_local_sh(std::get<PhotometricWeb>(web.model), order);
  const auto brute = sh_project(
      order,
      [&](Vec3 d) {
        return web.intensity(Vec3{d.x, -d.y, d.z});
      },
      sphere_quadrature(600, 1200));
  EXPECT_LT(max_abs_diff(exact, brute), 2e-5 * max_abs(exact));
  EXPECT_NEAR(std::sqrt(4 * kPi) * exact[0], web.flux_lm(), 1e-12 * web.flux_lm());
}

TEST(LuminaireSh, WebGammaQuadratureConverged) {
  const PhotometricWeb coarse = smooth_web(30.0, 45.0);
  for (const int order : {8, 16, 32}) {
    const auto w = web_local_sh(coarse, order);
    const auto fine = web_local_sh(coarse, order, 24);
    EXPECT_LT(max_abs_diff(w, fine), 1e-10 * max_abs(fine)) << order;
  }
}

TEST(LuminaireSh, LegendreAndFullPathsAgree) {
  Pcg32 rng(5, 9);
  for (const Distribution& d : {Distribution{axial_web()}, cosine_power(800.0, 20.0, 35.0)}) {
    ASSERT_TRUE(d.axisymmetric());
    for (const int order : {8, 16}) {
      const Vec3 aim = random_unit(rng);
      const Vec3 c0 = random_c0(rng, aim);
      const auto legendre =
          luminaire_world_sh(d, aim, c0, {.order = order, .path = LuminaireShPath::kLegendre});
      const auto full =
          luminaire_world_sh(d, aim, c0, {.order = order, .path = LuminaireShPath::kFull});
      const double rel = max_abs_diff(legendre, full) / max_abs(full);
      EXPECT_LT(rel, 1e-3) << order;
      EXPECT_LT(rel, 1e-8) << order;  // both are (near-)exact projections of the same function
    }
  }
  const Distribution c_dependent{smooth_web()};
  EXPECT_THROW(
      luminaire_world_sh(c_dependent, {0, 0, 1}, {1, 0, 0}, {.path = LuminaireShPath::kLegendre}),
      std::invalid_argument);
}

// Minimum and maximum of an SH series over a dense set of directions.
std::pair<double, double> series_range(const std::vector<double>& w) {
  const SphereQuadrature grid = sphere_quadrature(200, 400);
  double lo = 1e300, hi = -1e300;
  for (const Vec3& d : grid.directions) {
    const double v = sh_evaluate(w, d);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}

TEST(LuminaireSh, SigmaFactorReducesRingingOfANarrowSpot) {
  const Distribution spot = cosine_power(1000.0, 50.0, 20.0);
  const Vec3 aim = normalize(Vec3{0.3, -1, 0.2});
  const auto none =
      luminaire_world_sh(spot, aim, {1, 0, 0}, {.order = 8, .window = ShWindow::kNone});
  const auto sigma = luminaire_world_sh(spot, aim, {1, 0, 0}, {.order = 8});
  const auto hann =
      luminaire_world_sh(spot, aim, {1, 0, 0}, {.order = 8, .window = ShWindow::kHanning});
  const auto [none_min, none_max] = series_range(none);
  const auto [sigma_min, sigma_max] = series_range(sigma);
  const auto [hann_min, hann_max] = series_range(hann);
  EXPECT_LT(none_min, 0.0);
  EXPECT_GT(sigma_min, none_min);
  EXPECT_LT(std::abs(sigma_min), 0.5 * std::abs(none_min));
  EXPECT_GT(hann_min, none_min);
  RecordProperty("min_none_cd", std::to_string(none_min));
  RecordProperty("min_sigma_cd", std::to_string(sigma_min));
  RecordProperty("min_hanning_cd", std::to_string(hann_min));
  std::cout << "cos^50 cut 20°, order 8 (peak of the series; most negative value):\n"
            << "  none    " << none_max << " cd; " << none_min << " cd\n"
            << "  sigma   " << sigma_max << " cd; " << sigma_min << " cd\n"
            << "  hanning " << hann_max << " cd; " << hann_min << " cd\n";
}

TEST(LuminaireSh, BadArgumentsAreRefused) {
  const Distribution iso{IsotropicModel{1.0}};
  EXPECT_THROW(luminaire_world_sh(iso, {0, 0, 1}, {1, 0, 0}, {.order = 0}), std::invalid_argument);
  EXPECT_THROW(luminaire_world_sh(iso, {0, 0, 0}, {1, 0, 0}), std::invalid_argument);
  // c0 parallel to the aim: any perpendicular will do for a zonal distribution.
  const auto w = luminaire_world_sh(iso, {0, 0, 2}, {0, 0, 1});
  EXPECT_NEAR(sh_flux_lm(w), iso.flux_lm(), 1e-12);
}

}  // namespace
}  // namespace relight
