// Legendre weights of axisymmetric intensity distributions (Dobashi et al. 1995 Eq. 3, 19)
// and their incremental update when a control point moves (Eq. 21), math/zonal.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "math/legendre.h"
#include "math/sampling.h"
#include "math/test_util.h"
#include "math/vec3.h"
#include "math/zonal.h"

namespace relight {
namespace {

// (2l+1)/2 ∫_0^1 x P_l(x) dx: the weights of I(γ) = cosγ on γ < π/2, 0 beyond.
double cosine_hemisphere_weight(int l) {
  double integral;
  if (l == 0) {
    integral = 0.5;
  } else if (l == 1) {
    integral = 1.0 / 3.0;
  } else if (l % 2 == 1) {
    integral = 0.0;
  } else {
    // (−1)^{l/2+1} (l−2)! / (2^l (l/2−1)! (l/2+1)!)
    const int h = l / 2;
    integral = (h % 2 ? 1.0 : -1.0) * std::tgamma(l - 1.0) /
               (std::pow(2.0, l) * std::tgamma(h) * std::tgamma(h + 2.0));
  }
  return 0.5 * (2 * l + 1) * integral;
}

TEST(LegendreWeights, CosineOnUpperHemisphereMatchesClosedFormTo1e6) {
  const int n = 15;
  // M = 720: the kink at γ = π/2 falls on a Simpson panel boundary. Measured error <= 1.2e-8.
  const std::vector<double> w =
      legendre_weights([](double g) { return g < kPi / 2 ? std::cos(g) : 0.0; }, n, 720);
  for (int l = 0; l <= n; ++l) EXPECT_NEAR(w[l], cosine_hemisphere_weight(l), 1e-6) << l;
  EXPECT_NEAR(w[0], 0.25, 1e-9);
  EXPECT_NEAR(w[1], 0.5, 1e-9);
  EXPECT_NEAR(w[2], 5.0 / 16.0, 1e-9);
}

TEST(LegendreWeights, ConstantIntensityHasOnlyDegreeZeroTo1e6) {
  // Simpson's error on sinγ P_l(cosγ) grows like (l h)^4: measured 1e-10 at l = 0 and 3e-7 at
  // l = 10 with M = 360.
  const std::vector<double> w = legendre_weights([](double) { return 1.0; }, 10, 360);
  EXPECT_NEAR(w[0], 1.0, 1e-9);
  for (int l = 1; l <= 10; ++l) EXPECT_NEAR(w[l], 0.0, 1e-6);
}

TEST(LegendreWeights, SimpsonConvergesAtFourthOrderTrapezoidAtSecond) {
  // Reference: Gauss–Legendre in x = cosγ (exact to rounding for this entire function).
  const auto intensity = [](double g) { return std::exp(std::cos(g)); };
  const int n = 6;
  std::vector<double> ref(n + 1);
  zonal_to_legendre(zonal_project(
                        n + 1, [](double x) { return std::exp(x); }, 40),
                    ref);
  const auto error = [&](int m, IntegrationRule rule) {
    return test::max_abs_diff(legendre_weights(intensity, n, m, rule), ref);
  };
  const double s1 = error(32, IntegrationRule::kSimpson), s2 = error(64, IntegrationRule::kSimpson);
  const double t1 = error(32, IntegrationRule::kTrapezoid),
               t2 = error(64, IntegrationRule::kTrapezoid);
  EXPECT_NEAR(s1 / s2, 16.0, 2.0);
  EXPECT_NEAR(t1 / t2, 4.0, 0.5);
  EXPECT_LT(error(360, IntegrationRule::kSimpson), 1e-7);
}

TEST(LegendreWeights, TrapezoidOptionIsThePapersEq19Literally) {
  // w_l = (2l+1)/2 {½(I(0)f_l(0) + I(π)f_l(π)) + Σ_{i=1}^{M−1} I(iΔγ) f_l(iΔγ)} Δγ.
  const int m = 36, n = 8;
  const double dg = kPi / m;
  const auto intensity = [](double g) { return 1.0 + std::cos(3 * g) * std::sin(g); };
  const std::vector<double> w = legendre_weights(intensity, n, m, IntegrationRule::kTrapezoid);
  for (int l = 0; l <= n; ++l) {
    const auto f = [l](double g) { return legendre(l, std::cos(g)) * std::sin(g); };
    double sum = 0.5 * (intensity(0) * f(0) + intensity(kPi) * f(kPi));
    for (int i = 1; i < m; ++i) sum += intensity(i * dg) * f(i * dg);
    EXPECT_NEAR(w[l], 0.5 * (2 * l + 1) * sum * dg, 1e-14) << l;
  }
}

LegendreCurve test_curve(int controls, int intervals, IntegrationRule rule) {
  std::vector<double> g(controls), v(controls);
  for (int k = 0; k < controls; ++k) {
    g[k] = kPi * k / (controls - 1);
    v[k] = std::max(0.0, std::cos(g[k])) * 100.0 + 5.0;  // a downlight, in cd
  }
  g.back() = kPi;
  return make_legendre_curve(g, v, 15, intervals, rule);
}

TEST(LegendreWeights, IncrementalUpdateEqualsFullRecomputationTo1e12) {
  for (const IntegrationRule rule : {IntegrationRule::kSimpson, IntegrationRule::kTrapezoid}) {
    // 19 control points (every 10°), 360 intervals: 18 samples per segment.
    LegendreCurve c = test_curve(19, 360, rule);
    EXPECT_LT(test::max_abs_diff(c.weights, recompute_legendre_weights(c)), 1e-15);
    Pcg32 rng(51, 52);
    double worst = 0.0;
    for (int move = 0; move < 300; ++move) {
      const int k = static_cast<int>(rng.next_u32() % 19);
      const double value = 200.0 * rng.next_double();
      if (k == 0 || k == 18 || move % 2 == 0) {
        move_control_point(c, k, value);
      } else {  // also slide it in γ between its neighbours
        const double lo = c.control_gamma[k - 1], hi = c.control_gamma[k + 1];
        move_control_point(c, k, lo + (hi - lo) * (0.05 + 0.9 * rng.next_double()), value);
      }
      worst = std::max(worst, test::max_abs_diff(c.weights, recompute_legendre_weights(c)));
    }
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(LegendreWeights, MoveTouchesOnlySamplesBetweenNeighbours) {
  // Paper's setting: one control point per sample (M + 1 = 37): exactly one Simpson term.
  LegendreCurve one = test_curve(37, 36, IntegrationRule::kSimpson);
  EXPECT_EQ(move_control_point(one, 10, 42.0), 1);
  EXPECT_EQ(move_control_point(one, 0, 42.0), 1);
  EXPECT_EQ(move_control_point(one, 36, 42.0), 1);
  EXPECT_LT(test::max_abs_diff(one.weights, recompute_legendre_weights(one)), 1e-12);
  // Eq. 21 literally for interior k: Δw_l = (2l+1)/2 t_k ΔI f_l(γ_k) Δγ.
  const std::vector<double> before = one.weights;
  const int k = 7;
  const double delta = 13.0;
  move_control_point(one, k, one.control_value[k] + delta);
  const double gk = kPi * k / 36;
  for (int l = 0; l <= 15; ++l) {
    const double expected = 0.5 * (2 * l + 1) *
                            integration_weight(IntegrationRule::kSimpson, k, 36) * delta *
                            legendre(l, std::cos(gk)) * std::sin(gk);
    EXPECT_NEAR(one.weights[l] - before[l], expected, 1e-12);
  }
  // Coarser control points: the samples strictly inside (γ_{k−1}, γ_{k+1}).
  LegendreCurve coarse = test_curve(19, 360, IntegrationRule::kSimpson);
  EXPECT_EQ(move_control_point(coarse, 5, 1.0), 39);  // 2 segments of 20 intervals, minus ends
  EXPECT_EQ(move_control_point(coarse, 0, 1.0), 20);  // γ = 0 .. below γ_1
  EXPECT_EQ(move_control_point(coarse, 18, 1.0), 20);
}

TEST(LegendreWeights, BadInputThrowsInsteadOfCorrupting) {
  EXPECT_THROW(legendre_weights([](double) { return 1.0; }, 4, 35), std::invalid_argument);
  EXPECT_NO_THROW(legendre_weights([](double) { return 1.0; }, 4, 35, IntegrationRule::kTrapezoid));
  EXPECT_THROW(make_legendre_curve({0.0, 1.0}, {1.0, 1.0}, 4, 36), std::invalid_argument);
  EXPECT_THROW(make_legendre_curve({0.0, 2.0, 1.0, kPi}, {1, 1, 1, 1}, 4, 36),
               std::invalid_argument);
  LegendreCurve c = test_curve(5, 36, IntegrationRule::kSimpson);
  EXPECT_THROW(move_control_point(c, 5, 1.0), std::out_of_range);
  EXPECT_THROW(move_control_point(c, 2, c.control_gamma[3], 1.0), std::invalid_argument);
  EXPECT_LT(test::max_abs_diff(c.weights, recompute_legendre_weights(c)), 1e-15);
}

}  // namespace
}  // namespace relight
