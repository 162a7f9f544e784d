// Type-C web: symmetry expansion, bilinear evaluation with wrap-around, flux, openings.
#include "light/photometric_web.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "photometry_test_support.h"

namespace relight {
namespace {

// Stored planes whose values encode (plane, γ index) so copies can be traced.
std::vector<double> traced_values(std::size_t planes, std::size_t ng) {
  std::vector<double> v;
  for (std::size_t p = 0; p < planes; ++p) {
    for (std::size_t g = 0; g < ng; ++g) v.push_back(100.0 * (p + 1) + g);
  }
  return v;
}

std::size_t plane_at(const PhotometricWeb& web, double c_deg) {
  for (std::size_t i = 0; i < web.c_deg.size(); ++i) {
    if (std::abs(web.c_deg[i] - c_deg) < 1e-9) return i;
  }
  ADD_FAILURE() << "no plane at C" << c_deg;
  return 0;
}

// Expects the web's plane at `c` to hold stored plane `p` exactly.
void expect_plane(const PhotometricWeb& web, double c, std::size_t p) {
  const std::size_t ic = plane_at(web, c);
  for (std::size_t g = 0; g < web.gamma_deg.size(); ++g) {
    EXPECT_EQ(web.at(ic, g), 100.0 * (p + 1) + g) << "C" << c << " γ index " << g;
  }
}

const std::vector<double> kGamma = {0, 45, 90, 135, 180};

TEST(PhotometricWeb, QuadrantSymmetryMirrorsIntoAllFourQuadrants) {
  const auto web = make_web({0, 30, 90}, kGamma, traced_values(3, 5), CSymmetry::kQuadrant);
  EXPECT_EQ(web.c_deg, (std::vector<double>{0, 30, 90, 150, 180, 210, 270, 330, 360}));
  for (const double c : {0.0, 180.0, 360.0}) expect_plane(web, c, 0);
  for (const double c : {30.0, 150.0, 210.0, 330.0}) expect_plane(web, c, 1);
  for (const double c : {90.0, 270.0}) expect_plane(web, c, 2);
}

TEST(PhotometricWeb, BilateralC0C180MirrorsAcrossTheC0Plane) {
  const auto web = make_web({0, 60, 180}, kGamma, traced_values(3, 5), CSymmetry::kBilateralC0C180);
  EXPECT_EQ(web.c_deg, (std::vector<double>{0, 60, 180, 300, 360}));
  expect_plane(web, 60, 1);
  expect_plane(web, 300, 1);
  expect_plane(web, 360, 0);
}

TEST(PhotometricWeb, BilateralC90C270MirrorsAcrossTheC90Plane) {
  const auto web =
      make_web({90, 135, 180, 225, 270}, kGamma, traced_values(5, 5), CSymmetry::kBilateralC90C270);
  EXPECT_EQ(web.c_deg, (std::vector<double>{0, 45, 90, 135, 180, 225, 270, 315, 360}));
  expect_plane(web, 0, 2);    // I(0) = I(180)
  expect_plane(web, 45, 1);   // I(45) = I(135)
  expect_plane(web, 315, 3);  // I(315) = I(-135) = I(225)
  expect_plane(web, 360, 2);
}

TEST(PhotometricWeb, AxialSymmetryUsesTheOnePlaneEverywhere) {
  const auto web = make_web({0}, kGamma, traced_values(1, 5), CSymmetry::kAxial);
  EXPECT_EQ(web.c_deg, (std::vector<double>{0, 360}));
  EXPECT_TRUE(is_axisymmetric(web));
  EXPECT_DOUBLE_EQ(intensity(web, radians(123), radians(45)), 101.0);
}

TEST(PhotometricWeb, FullDataEndingBefore360WrapsToTheC0Plane) {
  const auto web = make_web({0, 120, 240}, kGamma, traced_values(3, 5), CSymmetry::kNone);
  EXPECT_EQ(web.c_deg, (std::vector<double>{0, 120, 240, 360}));
  expect_plane(web, 360, 0);
  // Halfway between C240 (plane 2) and C360 = C0 (plane 0), at γ index 1.
  EXPECT_NEAR(intensity(web, radians(300), radians(45)), 0.5 * (301 + 101), 1e-9);
  EXPECT_FALSE(is_axisymmetric(web));
}

TEST(PhotometricWeb, FullDataStartingAfter0InterpolatesAcrossTheGap) {
  const auto web = make_web({10, 190}, kGamma, traced_values(2, 5), CSymmetry::kNone);
  ASSERT_EQ(web.c_deg, (std::vector<double>{0, 10, 190, 360}));
  // C0 lies 10/180 of the way from C190 (going through 360) back to C10.
  const double expected = 200.0 + (100.0 - 200.0) * (170.0 / 180.0);
  EXPECT_NEAR(web.at(0, 0), expected, 1e-9);
  EXPECT_NEAR(intensity(web, radians(355), 0.0), intensity(web, radians(-5), 0.0), 1e-12);
}

TEST(PhotometricWeb, IntensityIsBilinearInCAndGamma) {
  const auto web =
      make_web({0, 90, 180, 270}, {0, 90}, {0, 10, 20, 30, 40, 50, 60, 70}, CSymmetry::kNone);
  // Planes: C0 (0,10), C90 (20,30), C180 (40,50), C270 (60,70), C360 = C0.
  EXPECT_NEAR(intensity(web, radians(45), radians(45)), 0.25 * (0 + 10 + 20 + 30), 1e-9);
  EXPECT_NEAR(intensity(web, radians(135), radians(22.5)), 0.75 * 30 + 0.25 * 40, 1e-9);
}

TEST(PhotometricWeb, IntensityWrapsAroundInC) {
  const auto web =
      make_web({0, 90, 180, 270}, {0, 90}, {0, 10, 20, 30, 40, 50, 60, 70}, CSymmetry::kNone);
  const double at_315 = intensity(web, radians(315), radians(90));
  EXPECT_NEAR(at_315, 0.5 * (70 + 10), 1e-9);  // between C270 and C360 = C0
  EXPECT_NEAR(intensity(web, radians(-45), radians(90)), at_315, 1e-9);
  EXPECT_NEAR(intensity(web, radians(675), radians(90)), at_315, 1e-9);
}

TEST(PhotometricWeb, IntensityIsZeroOutsideTheMeasuredGammaRange) {
  const auto down = make_web({0}, {0, 45, 90}, {10, 10, 10}, CSymmetry::kAxial);
  EXPECT_EQ(intensity(down, 0, radians(90)), 10.0);
  EXPECT_EQ(intensity(down, 0, radians(90.5)), 0.0);
  const auto up = make_web({0}, {90, 135, 180}, {10, 10, 10}, CSymmetry::kAxial);
  EXPECT_EQ(intensity(up, 0, radians(89)), 0.0);
  EXPECT_EQ(intensity(up, 0, radians(180)), 10.0);
}

TEST(PhotometricWeb, GammaBeyondThePoleFoldsOntoTheOppositePlane) {
  const auto web = make_web({0, 90, 180, 270}, {0, 90, 180}, traced_values(4, 3), CSymmetry::kNone);
  EXPECT_NEAR(intensity(web, radians(30), radians(-40)), intensity(web, radians(210), radians(40)),
              1e-9);
  EXPECT_NEAR(intensity(web, radians(30), radians(200)), intensity(web, radians(210), radians(160)),
              1e-9);
}

TEST(PhotometricWeb, FluxOfAUniformSphereIs4PiI) {
  const auto web = make_web({0}, {0, 30, 180}, {7, 7, 7}, CSymmetry::kAxial);
  EXPECT_NEAR(flux_lm(web), 4 * kPi * 7, 1e-12 * 4 * kPi * 7);
}

TEST(PhotometricWeb, FluxOfAUniformLowerHemisphereIs2PiI) {
  const auto web = make_web({0, 90}, {0, 10, 90}, {5, 5, 5, 5, 5, 5}, CSymmetry::kQuadrant);
  EXPECT_NEAR(flux_lm(web), 2 * kPi * 5, 1e-12 * 2 * kPi * 5);
}

TEST(PhotometricWeb, FluxOfLinearRampMatchesClosedForm) {
  // I = 100·γ/π on [0, π]: ∫ 2π·I sinγ dγ = 200·∫ γ sinγ dγ = 200·π.
  const auto web = make_web({0}, {0, 180}, {0, 100}, CSymmetry::kAxial);
  EXPECT_NEAR(flux_lm(web), 200 * kPi, 1e-9);
}

TEST(PhotometricWeb, FluxIsTheIntegralOfTheInterpolatedIntensity) {
  // Irregular grids, no symmetry, partial γ range: the closed form must agree with an
  // independent quadrature of intensity() to well under 0.1 %.
  const std::vector<double> c = {0, 20, 75, 150, 200, 310};
  const std::vector<double> g = {0, 5, 17.5, 40, 66, 90, 120};
  std::vector<double> v;
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t j = 0; j < g.size(); ++j) v.push_back(50 + 40 * std::sin(0.7 * i + 1.3 * j));
  }
  const auto web = make_web(c, g, v, CSymmetry::kNone);
  const double reference = test::brute_force_flux(
      [&](double cr, double gr) { return intensity(web, cr, gr); }, 900, 1600);
  EXPECT_NEAR(flux_lm(web) / reference, 1.0, 2e-4);
}

TEST(PhotometricWeb, MaxIntensityIsTheLargestValue) {
  const auto web = make_web({0, 90}, {0, 90}, {1, 9, 4, 2}, CSymmetry::kQuadrant);
  EXPECT_EQ(max_intensity(web), 9.0);
}

TEST(PhotometricWeb, MakeWebRejectsInconsistentInput) {
  EXPECT_THROW(make_web({0}, {0}, {1}, CSymmetry::kAxial), std::invalid_argument);
  EXPECT_THROW(make_web({0}, {0, 90}, {1}, CSymmetry::kAxial), std::invalid_argument);
  EXPECT_THROW(make_web({0}, {90, 0}, {1, 1}, CSymmetry::kAxial), std::invalid_argument);
  EXPECT_THROW(make_web({0, 0}, {0, 90}, {1, 1, 1, 1}, CSymmetry::kNone), std::invalid_argument);
  EXPECT_THROW(make_web({0}, {0, 190}, {1, 1}, CSymmetry::kAxial), std::invalid_argument);
}

TEST(TiltFactor, InterpolatesLinearlyAndHoldsBeyondTheEnds) {
  const TiltTable t{1, {0, 30, 90}, {1.0, 0.9, 0.6}};
  EXPECT_DOUBLE_EQ(tilt_factor(t, 15), 0.95);
  EXPECT_DOUBLE_EQ(tilt_factor(t, 60), 0.75);
  EXPECT_DOUBLE_EQ(tilt_factor(t, -5), 1.0);
  EXPECT_DOUBLE_EQ(tilt_factor(t, 120), 0.6);
  EXPECT_DOUBLE_EQ(tilt_factor(TiltTable{}, 40), 1.0);
}

TEST(IesLuminousOpening, FollowsTheLm63SignTable) {
  using S = OpeningShape;
  struct Case {
    double w, l, h;
    S shape;
  };
  const Case cases[] = {
      {0, 0, 0, S::kPoint},
      {0.3, 0.6, 0, S::kRectangular},
      {0.3, 0.6, 0.1, S::kRectangularWithLuminousSides},
      {-0.2, -0.2, 0, S::kCircular},
      {-0.2, -0.4, 0, S::kEllipse},
      {-0.2, -0.2, 0.5, S::kVerticalCylinder},
      {-0.2, -0.3, 0.5, S::kVerticalEllipticalCylinder},
      {-0.2, -0.2, -0.2, S::kSphere},
      {-0.2, -0.3, -0.4, S::kEllipsoidalSpheroid},
      {-0.1, 1.2, -0.1, S::kHorizontalCylinderAlongLength},
      {-0.1, 1.2, -0.2, S::kHorizontalEllipticalCylinderAlongLength},
      {1.2, -0.1, -0.1, S::kHorizontalCylinderAlongWidth},
      {1.2, -0.1, -0.2, S::kHorizontalEllipticalCylinderAlongWidth},
      {-0.3, 0, -0.3, S::kVerticalCircleFacingC0},
      {-0.3, 0, -0.2, S::kVerticalEllipseFacingC0},
      {0, -0.3, -0.3, S::kVerticalCircleFacingC90},
      {0, -0.3, -0.2, S::kVerticalEllipseFacingC90},
      {-0.12, 0, 0, S::kCircular},             // pre-2002 "negative width = round"
      {-0.12, 0, 0.34, S::kVerticalCylinder},  // the same with a luminous height
      {-0.12, 0.34, 0.56, S::kIrregular},
  };
  for (const Case& c : cases) {
    const LuminousOpening o = ies_luminous_opening(c.w, c.l, c.h);
    EXPECT_EQ(o.shape, c.shape) << c.w << " " << c.l << " " << c.h << " -> " << to_string(o.shape);
    EXPECT_GE(o.width_m, 0);
    EXPECT_GE(o.length_m, 0);
    EXPECT_GE(o.height_m, 0);
  }
  const LuminousOpening legacy = ies_luminous_opening(-0.12, 0, 0);
  EXPECT_DOUBLE_EQ(legacy.width_m, 0.12);
  EXPECT_DOUBLE_EQ(legacy.length_m, 0.12);
}

}  // namespace
}  // namespace relight
