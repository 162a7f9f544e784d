// sources/luminaires/distribution_profile.h: the distribution editor's curves — the exact intensity
// in four C half-planes and its SH approximation with and without the window — against closed
// forms.
#include <cmath>

#include <gtest/gtest.h>

#include "sources/luminaires/distribution_profile.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {
namespace {

TEST(DistributionProfile, IsotropicIsExactAtEveryOrder) {
  const Distribution d{IsotropicModel{250}};
  const DistributionProfile p = distribution_profile(d, 3, ShWindow::kSigma, 19);
  ASSERT_EQ(p.gamma_deg.size(), 19u);
  EXPECT_EQ(p.gamma_deg.back(), 180);
  for (int plane = 0; plane < 4; ++plane) {
    for (std::size_t i = 0; i < 19; ++i) {
      EXPECT_EQ(p.exact[plane][i], 250);
      EXPECT_NEAR(p.sh[plane][i], 250, 1e-9);
      EXPECT_NEAR(p.sh_windowed[plane][i], 250, 1e-9);
    }
  }
  EXPECT_NEAR(p.flux_lm, 4 * kPi * 250, 1e-9);
}

// cos γ (a Lambertian emitter, zero below the horizon) has the Legendre series
// 1/4 + P1/2 + 5/16 P2 + 0·P3 − 3/32 P4 ...: at order 3 (l ≤ 2) at γ = 0 that is
// 1/4 + 1/2 + 5/16 = 1.0625; with sigma factors σ1 = sin(π/3)/(π/3), σ2 = sin(2π/3)/(2π/3).
TEST(DistributionProfile, LambertianMatchesItsLegendreSeries) {
  const Distribution d{CosinePowerModel{100, 1, kPi / 2}};
  const DistributionProfile p = distribution_profile(d, 3, ShWindow::kSigma, 181);
  const double s1 = std::sin(kPi / 3) / (kPi / 3), s2 = std::sin(2 * kPi / 3) / (2 * kPi / 3);
  EXPECT_NEAR(p.sh[0][0], 106.25, 1e-4);
  EXPECT_NEAR(p.sh_windowed[0][0], 100 * (0.25 + 0.5 * s1 + 5.0 / 16 * s2), 1e-4);
  // At γ = 90°: P1 = 0, P2 = −1/2.
  EXPECT_NEAR(p.sh[1][90], 100 * (0.25 - 5.0 / 32), 1e-4);
  EXPECT_NEAR(p.exact[2][60], 100 * std::cos(kPi / 3), 1e-9);
  // Axisymmetric: every plane the same.
  for (std::size_t i = 0; i < 181; ++i) EXPECT_NEAR(p.sh[3][i], p.sh[0][i], 1e-9);
}

TEST(DistributionProfile, RefusesBadArguments) {
  const Distribution d{IsotropicModel{1}};
  EXPECT_THROW(distribution_profile(d, 3, ShWindow::kSigma, 1), std::invalid_argument);
  EXPECT_THROW(distribution_profile(d, 0, ShWindow::kSigma, 10), std::invalid_argument);
}

}  // namespace
}  // namespace relight
