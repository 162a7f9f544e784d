// Zonal harmonics (math/zonal.h): rotating zonal coefficients to an axis by the addition
// theorem equals projecting the rotated axisymmetric function; Legendre ↔ zonal conversions.
#include "math/zonal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/legendre.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/sh_rotation.h"
#include "math/test_util.h"

namespace relight {
namespace {

TEST(ZonalRotation, EqualsProjectionOfRotatedBandLimitedFunctionTo1e11) {
  Pcg32 rng(41, 42);
  for (int order : {1, 3, 9, 16}) {
    std::vector<double> w(order);
    for (double& v : w) v = 2 * rng.next_double() - 1;
    std::vector<double> z(order);
    legendre_to_zonal(w, z);
    for (int trial = 0; trial < 3; ++trial) {
      const Vec3 axis = test::random_direction(rng);
      const std::vector<double> projected =
          sh_project(order, [&](Vec3 d) { return legendre_series(w, dot(axis, d)); });
      EXPECT_LT(test::max_abs_diff(zonal_rotate(z, axis), projected), 1e-11) << order;
    }
  }
}

TEST(ZonalRotation, EqualsProjectionOfRotatedSmoothLobeTo1e10) {
  // g(x) = exp(4x) is not band-limited; its coefficients fall off so fast that a rule exact to
  // degree 80 (and 40 Gauss nodes for the zonal projection) leave only rounding.
  const int order = 16;
  const auto g = [](double x) { return std::exp(4 * x); };
  const std::vector<double> z = zonal_project(order, g, 40);
  Pcg32 rng(43, 44);
  const SphereQuadrature fine = sphere_quadrature_exact_to_degree(80);
  for (int trial = 0; trial < 3; ++trial) {
    const Vec3 axis = test::random_direction(rng);
    const std::vector<double> projected = sh_project(
        order, [&](Vec3 d) { return g(dot(axis, d)); }, fine);
    EXPECT_LT(test::max_abs_diff(zonal_rotate(z, axis), projected), 1e-10);
  }
  // Along +z only the m = 0 terms survive and equal z_l.
  const std::vector<double> up = zonal_rotate(z, {0, 0, 1});
  for (int l = 0; l < order; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_NEAR(up[sh_index(l, m)], m == 0 ? z[l] : 0.0, 1e-13);
}

TEST(ZonalRotation, AgreesWithGeneralRotationOfZonalVectorTo1e12) {
  Pcg32 rng(45, 46);
  const int order = 20;
  std::vector<double> z(order);
  for (double& v : z) v = 2 * rng.next_double() - 1;
  std::vector<double> along_z(sh_count(order), 0.0);
  for (int l = 0; l < order; ++l) along_z[sh_index(l, 0)] = z[l];
  for (int trial = 0; trial < 5; ++trial) {
    const Mat3 r = test::random_rotation(rng);
    std::vector<double> rotated(along_z.size());
    sh_rotate(make_sh_rotation(order, r), along_z, rotated);
    EXPECT_LT(test::max_abs_diff(rotated, zonal_rotate(z, r * Vec3{0, 0, 1})), 1e-12);
  }
}

TEST(ZonalRotation, LegendreSeriesAndAimedShAgreeTo1e12) {
  // I(γ) = Σ w_l P_l(cosγ) aimed at `axis` (Dobashi Eq. 8-10) reconstructs to the same values.
  Pcg32 rng(47, 48);
  const int order = 12;
  std::vector<double> w(order), z(order), back(order);
  for (double& v : w) v = 2 * rng.next_double() - 1;
  legendre_to_zonal(w, z);
  zonal_to_legendre(z, back);
  EXPECT_LT(test::max_abs_diff(back, w), 1e-15);
  for (int l = 0; l < order; ++l) EXPECT_NEAR(z[l], std::sqrt(4 * kPi / (2 * l + 1)) * w[l], 1e-15);
  const Vec3 axis = normalize(Vec3{0.3, -0.5, 0.8});
  const std::vector<double> sh = zonal_rotate(z, axis);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 d = test::random_direction(rng);
    EXPECT_NEAR(sh_evaluate(sh, d), legendre_series(w, dot(axis, d)), 1e-12);
  }
  // Zonal projection of a Legendre series gives back its zonal coefficients.
  EXPECT_LT(
      test::max_abs_diff(zonal_project(order, [&](double x) { return legendre_series(w, x); }), z),
      1e-13);
}

}  // namespace
}  // namespace relight
