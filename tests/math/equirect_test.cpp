// Equirectangular maps: orientation, texel solid angles and SH projection (math/equirect.h).
#include "math/equirect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/sampling.h"
#include "math/sh.h"
#include "math/test_util.h"

namespace relight {
namespace {

TEST(Equirect, SolidAnglesSumTo4PiTo1e9) {
  for (const auto& [w, h] :
       {std::pair{1, 1}, std::pair{4, 2}, std::pair{360, 180}, std::pair{1024, 512}}) {
    double sum = 0.0;
    for (int j = 0; j < h; ++j) sum += w * equirect_row_solid_angle(w, h, j);
    EXPECT_NEAR(sum, 4 * kPi, 1e-9);
  }
}

TEST(Equirect, OrientationAsDocumented) {
  const auto near = [](Vec3 a, Vec3 b) { return length(a - b) < 1e-15; };
  EXPECT_TRUE(near(equirect_direction(0.3, 0.0), {0, 1, 0}));   // top row: +y
  EXPECT_TRUE(near(equirect_direction(0.3, 1.0), {0, -1, 0}));  // bottom row: −y
  EXPECT_TRUE(near(equirect_direction(0.0, 0.5), {0, 0, -1}));
  EXPECT_TRUE(near(equirect_direction(0.25, 0.5), {1, 0, 0}));
  EXPECT_TRUE(near(equirect_direction(0.5, 0.5), {0, 0, 1}));
  EXPECT_TRUE(near(equirect_direction(0.75, 0.5), {-1, 0, 0}));
  const EquirectUv uv = equirect_uv({1, 1, 0});
  EXPECT_NEAR(uv.u, 0.25, 1e-15);
  EXPECT_NEAR(uv.v, 0.25, 1e-15);
}

TEST(Equirect, DirectionToTexelRoundTripsEveryTexelCentre) {
  const int w = 64, h = 32;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Vec3 d = equirect_texel_direction(w, h, i, j);
      EXPECT_NEAR(length(d), 1.0, 1e-15);
      const EquirectTexel t = equirect_texel(w, h, d);
      EXPECT_EQ(t.i, i);
      EXPECT_EQ(t.j, j);
      const EquirectUv uv = equirect_uv(d);
      EXPECT_NEAR(uv.u, (i + 0.5) / w, 1e-14);
      EXPECT_NEAR(uv.v, (j + 0.5) / h, 1e-14);
    }
}

TEST(Equirect, ShProjectionRecoversBandLimitedCoefficients) {
  // Texels sampled at their centres from a random order-8 function (|c| <= 1): exact in φ,
  // midpoint rule in θ, O(1/H²); measured max errors 2.0e-4 (256×128) and 4.9e-5 (512×256),
  // and 2.2e-4 / 5.4e-5 for a constant map, so the tolerance is 4/H².
  Pcg32 rng(71, 72);
  const int order = 8;
  const std::vector<double> c = test::random_coefficients(rng, order);
  for (const int h : {128, 256}) {
    const int w = 2 * h;
    const double tol = 4.0 / (h * h);
    std::vector<double> texels(static_cast<std::size_t>(w) * h);
    std::vector<Rgb> rgb(texels.size());
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const double v = sh_evaluate(c, equirect_texel_direction(w, h, i, j));
        texels[static_cast<std::size_t>(j) * w + i] = v;
        rgb[static_cast<std::size_t>(j) * w + i] = {0.0, v, 1.0};
      }
    EXPECT_LT(test::max_abs_diff(sh_project_equirect(order, w, h, texels), c), tol) << w;
    const std::vector<Rgb> p = sh_project_equirect(order, w, h, rgb);
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(p[i].g, c[i], tol);
      // Row solid angles sum to 4π exactly: a constant's Y_00 coefficient is exact.
      EXPECT_NEAR(p[i].b, i == 0 ? std::sqrt(4 * kPi) : 0.0, i == 0 ? 1e-11 : tol);
    }
  }
}

}  // namespace
}  // namespace relight
