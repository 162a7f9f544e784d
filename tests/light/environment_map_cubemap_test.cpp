// Exact cubemap averages of equirectangular maps (Green's theorem in the equal-area plane):
// texel solid angles, constant maps, conservation, poles, and a brute-force comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "light/environment.h"
#include "light/environment_map_cubemap.h"
#include "math/cubemap.h"

namespace relight {
namespace {

double cube_integral_g(const std::vector<Rgb>& cube, int n) {
  double sum = 0;
  for (std::size_t t = 0; t < cube.size(); ++t) {
    const CubemapTexel c = cubemap_texel_from_index(n, t);
    sum += cube[t].g * cubemap_texel_solid_angle(n, c.i, c.j);
  }
  return sum;
}

std::shared_ptr<EquirectMap> random_map(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto map = std::make_shared<EquirectMap>();
  map->width = width;
  map->height = height;
  for (int k = 0; k < width * height; ++k) {
    map->texels.push_back({uniform(rng), uniform(rng), uniform(rng)});
  }
  return map;
}

// With f ≡ 1 the loop integral is the texel's solid angle: against the closed form, for odd
// and even face sizes (odd: the ±Y centre texels contain the poles) and coarse, odd maps.
TEST(EnvironmentMapCubemap, TexelSolidAnglesAreExact) {
  for (auto [w, h, n] :
       {std::tuple{64, 32, 1}, {64, 32, 2}, {64, 32, 3}, {7, 4, 5}, {10, 5, 33}, {1024, 512, 16}}) {
    double worst = 0;
    for (int face = 0; face < 6; ++face) {
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const double a = equirect_raster_texel_solid_angle(w, h, n, face, i, j);
          worst = std::max(worst, std::abs(a / cubemap_texel_solid_angle(n, i, j) - 1));
        }
      }
    }
    EXPECT_LT(worst, 1e-10) << w << "x" << h << " -> " << n;
  }
}

TEST(EnvironmentMapCubemap, ConstantMapGivesConstantCube) {
  for (auto [w, n] : {std::pair{16, 32}, {64, 3}, {256, 16}, {512, 8}}) {
    auto map = std::make_shared<EquirectMap>();
    map->width = w;
    map->height = w / 2;
    map->texels.assign(static_cast<std::size_t>(w) * (w / 2), Rgb{2, 3, 4});
    for (double rotate : {0.0, 17.0, -123.0}) {
      const std::vector<Rgb> cube = environment_cubemap(make_map_environment(map, rotate, 0.5), n);
      for (const Rgb& c : cube) {
        ASSERT_NEAR(c.r, 1.0, 1e-10);
        ASSERT_NEAR(c.g, 1.5, 1e-10);
        ASSERT_NEAR(c.b, 2.0, 1e-10);
      }
    }
  }
}

TEST(EnvironmentMapCubemap, ConservesTheMapIntegral) {
  const auto map = random_map(40, 20, 7);
  for (double rotate : {0.0, 33.0, 90.0}) {
    const Environment env = make_map_environment(map, rotate, 3.0);
    const double total = environment_integral(env).g;
    for (int n : {1, 2, 3, 8, 31}) {
      EXPECT_NEAR(cube_integral_g(environment_cubemap(env, n), n), total, 1e-10 * total)
          << "rotate " << rotate << " n " << n;
    }
  }
}

// One bright texel at a time, every texel of a coarse map (rows at the poles and at the
// horizon, the seam): its whole L·Ω reaches the cube.
TEST(EnvironmentMapCubemap, EverySingleTexelIsConserved) {
  const int w = 14, h = 7;
  for (int n : {1, 2, 3}) {
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        auto map = std::make_shared<EquirectMap>();
        map->width = w;
        map->height = h;
        map->texels.assign(w * h, Rgb{});
        map->texels[j * w + i] = {1, 1, 1};
        const Environment env = make_map_environment(map, 10.0, 1.0);
        EXPECT_NEAR(cube_integral_g(environment_cubemap(env, n), n), environment_integral(env).g,
                    1e-12)
            << "texel " << i << ", " << j << " n " << n;
      }
    }
  }
}

// Against brute force: the texel average by 350 × 350 sub-samples per texel (exact solid-angle
// weights), whose own error on a discontinuous map is ~1e-3.
TEST(EnvironmentMapCubemap, MatchesBruteForceAverages) {
  const auto map = random_map(16, 8, 11);
  const Environment env = make_map_environment(map, 21.0, 1.0);
  const int n = 2;
  const std::vector<Rgb> cube = environment_cubemap(env, n);
  constexpr int kSamples = 350;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        double sum = 0, weight = 0;
        for (int b = 0; b < kSamples; ++b) {
          for (int a = 0; a < kSamples; ++a) {
            const double s = (i + (a + 0.5) / kSamples) / n, t = (j + (b + 0.5) / kSamples) / n;
            const double u = 2 * s - 1, v = 2 * t - 1;
            const double w = 1 / std::pow(1 + u * u + v * v, 1.5);
            sum += env.radiance(cubemap_direction({face, s, t})).g * w;
            weight += w;
          }
        }
        EXPECT_NEAR(cube[cubemap_texel_index(n, {face, i, j})].g, sum / weight, 2e-3)
            << face << " " << i << " " << j;
      }
    }
  }
}

// A map bright only in its top row: all of it lands in the +Y face (the pole texel for odd N).
TEST(EnvironmentMapCubemap, PoleRowLandsOnTopFace) {
  auto map = std::make_shared<EquirectMap>();
  map->width = 64;
  map->height = 32;
  map->texels.assign(64 * 32, Rgb{});
  for (int i = 0; i < 64; ++i) map->texels[i] = {1, 1, 1};
  const Environment env = make_map_environment(map, 0.0, 1.0);
  const int n = 3;
  const std::vector<Rgb> cube = environment_cubemap(env, n);
  const double total = environment_integral(env).g;
  const CubemapTexel centre{kPosY, 1, 1};
  EXPECT_NEAR(cube[cubemap_texel_index(n, centre)].g * cubemap_texel_solid_angle(n, 1, 1), total,
              1e-12);
  EXPECT_NEAR(cube_integral_g(cube, n), total, 1e-12);
}

}  // namespace
}  // namespace relight
