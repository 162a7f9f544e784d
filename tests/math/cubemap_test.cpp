// Cubemap layout, exact texel solid angles and SH projection (math/cubemap.h).
#include "math/cubemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/legendre.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/test_util.h"

namespace relight {
namespace {

TEST(Cubemap, SolidAnglesSumTo4PiTo1e9) {
  for (int n : {1, 2, 7, 64, 256}) {
    double sum = 0.0;
    for (double o : cubemap_solid_angles(n)) sum += 6 * o;
    EXPECT_NEAR(sum, 4 * kPi, 1e-9) << n;
  }
  EXPECT_NEAR(cubemap_texel_solid_angle(1, 0, 0), 4 * kPi / 6, 1e-14);
}

TEST(Cubemap, TexelSolidAngleMatchesAreaElementQuadratureTo1e13) {
  // ∫∫ du dv / (1 + u² + v²)^{3/2} over the texel by 20×20 Gauss–Legendre.
  const int n = 8;
  const GaussLegendre gl = gauss_legendre(20);
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{3, 5}, std::pair{7, 2}}) {
    const double u0 = 2.0 * i / n - 1, v0 = 2.0 * j / n - 1, h = 2.0 / n;
    double sum = 0.0;
    for (int a = 0; a < 20; ++a)
      for (int b = 0; b < 20; ++b) {
        const double u = u0 + 0.5 * h * (gl.nodes[a] + 1), v = v0 + 0.5 * h * (gl.nodes[b] + 1);
        sum += 0.25 * h * h * gl.weights[a] * gl.weights[b] / std::pow(1 + u * u + v * v, 1.5);
      }
    EXPECT_NEAR(cubemap_texel_solid_angle(n, i, j), sum, 1e-13);
  }
}

TEST(Cubemap, FaceOrderAndOrientationFollowOpenGL) {
  const Vec3 centre[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Directions of growing s and growing t on each face (OpenGL Table 8.19).
  const Vec3 s_dir[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
  const Vec3 t_dir[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) {
    const Vec3 c = cubemap_direction({f, 0.5, 0.5});
    EXPECT_NEAR(length(c - centre[f]), 0.0, 1e-15) << f;
    const Vec3 ds = cubemap_direction({f, 0.75, 0.5}) - c;
    const Vec3 dt = cubemap_direction({f, 0.5, 0.75}) - c;
    // (The step also moves toward the face centre's axis a little: cos = 0.973.)
    EXPECT_GT(dot(normalize(ds), s_dir[f]), 0.97) << f;
    EXPECT_GT(dot(normalize(dt), t_dir[f]), 0.97) << f;
    EXPECT_NEAR(dot(ds, t_dir[f]), 0.0, 1e-15) << f;
    EXPECT_NEAR(dot(dt, s_dir[f]), 0.0, 1e-15) << f;
  }
  // Corner texel (0, 0) of +Z is toward −x, +y.
  const Vec3 corner = cubemap_texel_direction(4, {kPosZ, 0, 0});
  EXPECT_LT(corner.x, 0);
  EXPECT_GT(corner.y, 0);
  EXPECT_EQ(cubemap_texel_index(4, {kNegY, 1, 2}), (3u * 4 + 2) * 4 + 1);
  const CubemapTexel back = cubemap_texel_from_index(4, (3u * 4 + 2) * 4 + 1);
  EXPECT_EQ(back.face, kNegY);
  EXPECT_EQ(back.i, 1);
  EXPECT_EQ(back.j, 2);
}

TEST(Cubemap, DirectionToTexelRoundTripsEveryTexelCentre) {
  const int n = 16;
  for (std::size_t idx = 0; idx < cubemap_texel_count(n); ++idx) {
    const CubemapTexel t = cubemap_texel_from_index(n, idx);
    const Vec3 d = cubemap_texel_direction(n, t);
    EXPECT_NEAR(length(d), 1.0, 1e-15);
    EXPECT_EQ(cubemap_texel_index(n, cubemap_texel(n, d)), idx);
    EXPECT_EQ(cubemap_texel_index(n, cubemap_texel(n, d * 3.7)), idx);  // any length
    const CubemapCoord c = cubemap_coord(d);
    EXPECT_NEAR(c.s, (t.i + 0.5) / n, 1e-14);
    EXPECT_NEAR(c.t, (t.j + 0.5) / n, 1e-14);
  }
}

TEST(Cubemap, ShProjectionRecoversBandLimitedCoefficients) {
  // Texels sampled at their centres from a random order-8 function (|c| <= 1): the texel
  // midpoint rule errs by O(1/N²); measured max errors 2.4e-4 (N = 64) and 6.0e-5 (N = 128),
  // and 4.1e-4 / 1.0e-4 for a constant map, so the tolerance is 2/N².
  Pcg32 rng(61, 62);
  const int order = 8;
  const std::vector<double> c = test::random_coefficients(rng, order);
  for (const int n : {64, 128}) {
    const double tol = 2.0 / (n * n);
    std::vector<double> texels(cubemap_texel_count(n));
    std::vector<Rgb> rgb(texels.size());
    for (std::size_t i = 0; i < texels.size(); ++i) {
      texels[i] = sh_evaluate(c, cubemap_texel_direction(n, cubemap_texel_from_index(n, i)));
      rgb[i] = {texels[i], 1.0, 0.0};
    }
    EXPECT_LT(test::max_abs_diff(sh_project_cubemap(order, n, texels), c), tol) << n;
    const std::vector<Rgb> p = sh_project_cubemap(order, n, rgb);
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(p[i].r, c[i], tol);
      // Σ Ω = 4π exactly, so a constant's Y_00 coefficient is exact; the rest is midpoint error.
      EXPECT_NEAR(p[i].g, i == 0 ? std::sqrt(4 * kPi) : 0.0, i == 0 ? 1e-12 : tol);
    }
  }
}

}  // namespace
}  // namespace relight
