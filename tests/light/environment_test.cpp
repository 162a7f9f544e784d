// Environments: uniform SH, the sun's SH irradiance at high order, the sky SH against brute
// force, cubemap energy conservation, map rotation, and building from specs.
#include <gtest/gtest.h>

#include "support/cubemap_integral.h"

#include <cmath>
#include <iostream>
#include <memory>

#include "light/environment.h"
#include "light/perez_sky.h"
#include "light/sun_position.h"
#include "math/cubemap.h"
#include "math/equirect.h"
#include "math/legendre.h"
#include "math/sh.h"

namespace relight {
namespace {

// Â_l = 2π ∫_0^1 P_l(t) t dt: the clamped-cosine kernel of irradiance, E(n) = Σ Â_l Σ_m c_lm
// Y_lm(n) (Ramamoorthi & Hanrahan 2001). Gauss–Legendre on [0, 1] is exact for it.
std::vector<double> clamped_cosine(int order) {
  const GaussLegendre gl = gauss_legendre(order + 2);
  std::vector<double> a(order, 0.0);
  for (std::size_t k = 0; k < gl.nodes.size(); ++k) {
    const double t = 0.5 * (gl.nodes[k] + 1), w = 0.5 * gl.weights[k];
    for (int l = 0; l < order; ++l) a[l] += 2 * kPi * legendre(l, t) * t * w;
  }
  return a;
}

double irradiance_from_sh(const std::vector<Rgb>& c, Vec3 normal) {
  const int order = sh_order_from_count(c.size());
  const std::vector<double> a = clamped_cosine(order);
  std::vector<double> y(c.size());
  sh_eval(order, normal, y);
  double e = 0;
  for (int l = 0; l < order; ++l) {
    for (int m = -l; m <= l; ++m) e += a[l] * luminance(c[sh_index(l, m)]) * y[sh_index(l, m)];
  }
  return e;
}

using testing::cube_integral;

// A smooth, non-symmetric map with a bright small blob: per-texel values in cd/m².
std::shared_ptr<EquirectMap> test_map(int width, int height) {
  auto map = std::make_shared<EquirectMap>();
  map->width = width;
  map->height = height;
  map->texels.resize(static_cast<std::size_t>(width) * height);
  const Vec3 blob = normalize(Vec3{0.3, 0.6, 0.5});
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const Vec3 d = equirect_texel_direction(width, height, i, j);
      const double sky = d.y > 0 ? 1000 + 800 * d.y + 300 * d.x : 150 + 20 * d.z;
      const double hot = dot(d, blob) > 0.995 ? 50000.0 : 0.0;
      map->texels[static_cast<std::size_t>(j) * width + i] = {sky * 1.1 + hot, sky + hot,
                                                              sky * 0.8 + hot};
    }
  }
  return map;
}

TEST(Environment, UniformShIsOnlyL00) {
  const Environment env = make_uniform_environment({1200, 1000, 700});
  const std::vector<Rgb> c = environment_sh(env, 8);
  ASSERT_EQ(c.size(), 64u);
  EXPECT_DOUBLE_EQ(c[0].r, std::sqrt(4 * kPi) * 1200);
  EXPECT_DOUBLE_EQ(c[0].g, std::sqrt(4 * kPi) * 1000);
  EXPECT_DOUBLE_EQ(c[0].b, std::sqrt(4 * kPi) * 700);
  for (std::size_t i = 1; i < c.size(); ++i) {
    EXPECT_EQ(c[i].r, 0.0);
    EXPECT_EQ(c[i].g, 0.0);
    EXPECT_EQ(c[i].b, 0.0);
  }
  // The irradiance of a uniform environment on any plane is π L.
  EXPECT_NEAR(irradiance_from_sh(c, normalize(Vec3{1, 2, 3})),
              kPi * luminance(env.uniform_radiance), 1e-9);
}

TEST(Environment, UniformFromSpecKeepsLuminanceAndTint) {
  EnvironmentSpec spec;
  spec.type = EnvironmentType::kUniform;
  spec.luminance = 2500;
  spec.color = {1.0, 0.8, 0.5};
  const Environment env = make_environment(spec);
  EXPECT_NEAR(luminance(env.radiance({0, -1, 0})), 2500, 1e-9);
  EXPECT_NEAR(env.uniform_radiance.r / env.uniform_radiance.b, 2.0, 1e-12);
  EXPECT_FALSE(env.sun().has_value());
}

// A sky of nothing but the sun: the clamped-cosine irradiance of its SH on a plane facing the
// sun tends to the sun's normal illuminance as the order grows.
TEST(Environment, SunShIrradianceApproachesNormalIlluminance) {
  const double e_sun = 100000.0;
  const Vec3 dir = horizontal_to_world(200, 40);
  const Environment env =
      make_sky_environment(make_sky_from_zenith_luminance(5, dir, 0.0, 0.0, e_sun));
  ASSERT_TRUE(env.sun().has_value());
  double previous = 1;
  for (int order : {4, 8, 16, 32, 64}) {
    const double e = irradiance_from_sh(environment_sh(env, order), env.sun()->direction);
    const double err = std::abs(e / e_sun - 1);
    std::cout << "[ measured ] sun-only sky, order " << order
              << ": E(normal to sun) from SH / E_sun = " << e / e_sun << "\n";
    if (order >= 16) {
      EXPECT_LT(err, previous);
    }
    previous = err;
    if (order == 32) {
      EXPECT_LT(err, 5e-3);
    }
    if (order == 64) {
      EXPECT_LT(err, 2e-3);
    }
  }
  // At low order the closed-form cap equals the delta E·Y_lm(s), E = ∫_disc L dω.
  const std::vector<Rgb> c = environment_sh(env, 4);
  std::vector<double> y(16);
  sh_eval(4, env.sun()->direction, y);
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(c[i].g, env.sun()->integrated_luminance() * y[i], 1e-4 * e_sun) << i;
  }
}

// The sky's SH (dome quadrature + closed-form ground) against a brute-force projection of the
// same radiance with a fine sphere rule.
TEST(Environment, SkyShMatchesBruteForce) {
  const Vec3 sun = horizontal_to_world(135, 35);
  for (int type : {0, 3, 12, 15}) {
    const Environment env =
        make_sky_environment(make_sky_from_horizontal_illuminance(type, sun, 20000.0, 0.25, 0));
    const std::vector<Rgb> c = environment_sh(env, 6);
    const std::vector<Rgb> brute = sh_project_rgb(
        6, [&](Vec3 d) { return env.radiance(d); }, sphere_quadrature(500, 1000));
    double worst = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      worst = std::max(worst, std::abs(c[i].g - brute[i].g));
    EXPECT_LT(worst, 1e-4 * c[0].g) << "type " << type;
    std::cout << "[ measured ] sky type " << type
              << " SH order 6 vs brute force: max |Δc| / c00 = " << worst / c[0].g << "\n";
  }
}

TEST(Environment, SkyIntegralAndUpwardIrradiance) {
  const Vec3 sun = horizontal_to_world(160, 50);
  const SkyModel sky = make_sky_from_horizontal_illuminance(12, sun, 18000.0, 0.2, 70000.0);
  const Environment env = make_sky_environment(sky);
  // c00·sqrt(4π) = ∫ L dω, everything included.
  const std::vector<Rgb> c = environment_sh(env, 12);
  const double integral = luminance(environment_integral(env));
  EXPECT_NEAR(c[0].g * std::sqrt(4 * kPi), integral, 1e-6 * integral);
  // The upward irradiance of the SH approximates E_h,sky + E_h,sun (clamped cosine, order 12).
  const double e_up = irradiance_from_sh(c, {0, 1, 0});
  const double exact = 18000.0 + 70000.0 * sun.y;
  EXPECT_NEAR(e_up, exact, 0.02 * exact);
  std::cout << "[ measured ] clear sky + sun, upward irradiance from SH order 12: " << e_up
            << " lx vs " << exact << " lx (" << (e_up / exact - 1) * 100 << " %)\n";
}

TEST(Environment, CubemapConservesIntegral) {
  // Uniform.
  const Environment uniform = make_uniform_environment({3, 2, 1});
  const double u = luminance(environment_integral(uniform));
  EXPECT_NEAR(cube_integral(environment_cubemap(uniform, 16), 16), u, 1e-12 * u);
  // Skies with sun and ground, even and odd face sizes (odd: the horizon crosses texels).
  for (int type : {0, 7, 12}) {
    const Environment sky = make_sky_environment(make_sky_from_horizontal_illuminance(
        type, horizontal_to_world(120, 25), 15000.0, 0.2, type == 0 ? 0.0 : 60000.0));
    const double total = luminance(environment_integral(sky));
    for (int n : {8, 32, 33}) {
      const double got = cube_integral(environment_cubemap(sky, n), n);
      EXPECT_NEAR(got, total, 1e-3 * total) << "type " << type << " n " << n;
      std::cout << "[ measured ] sky type " << type << " cubemap " << n
                << ": Σ LΩ / ∫ L dω - 1 = " << got / total - 1 << "\n";
    }
  }
  // Map: exact by construction (light/environment_map_cubemap.h), also rotated.
  const Environment map = make_map_environment(test_map(256, 128), 33.0, 2.0);
  const double m = luminance(environment_integral(map));
  for (int n : {4, 32, 51}) {
    const double got = cube_integral(environment_cubemap(map, n), n);
    EXPECT_NEAR(got, m, 1e-9 * m) << "n " << n;
  }
}

TEST(Environment, CubemapHoldsTheSunInItsTexel) {
  const Vec3 sun = horizontal_to_world(200, 40);
  const Environment env =
      make_sky_environment(make_sky_from_zenith_luminance(5, sun, 0.0, 0.0, 90000.0));
  const int n = 32;
  const std::vector<Rgb> cube = environment_cubemap(env, n);
  const CubemapTexel t = cubemap_texel(n, env.sun()->direction);
  const double omega = cubemap_texel_solid_angle(n, t.i, t.j);
  EXPECT_NEAR(cube[cubemap_texel_index(n, t)].g * omega, env.sun()->integrated_luminance(),
              1e-9 * 90000.0);
  EXPECT_NEAR(cube_integral(cube, n), env.sun()->integrated_luminance(), 1e-9 * 90000.0);
}

// A sky cubemap texel is the average radiance over the texel.
TEST(Environment, SkyCubemapTexelsAreAverages) {
  const Environment env =
      make_sky_environment(make_sky_from_zenith_luminance(0, {0, 1, 0}, 3000.0, 0.2, 0));
  const int n = 16;
  const std::vector<Rgb> cube = environment_cubemap(env, n);
  // +Y face centre texels: the overcast sky is almost flat there.
  const CubemapTexel top{kPosY, n / 2, n / 2};
  EXPECT_NEAR(cube[cubemap_texel_index(n, top)].g, env.radiance(cubemap_texel_direction(n, top)).g,
              1e-3 * 3000.0);
  // Every −Y texel sees the uniform ground.
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(cube[cubemap_texel_index(n, {kNegY, i, j})].g, env.sky.ground_luminance, 1e-9);
    }
  }
}

// rotate_deg turns the map clockwise seen from above: a bright texel due north (−z) appears
// due east (+x) after rotate_deg = 90, south after 180.
TEST(Environment, MapRotateMovesTexelClockwise) {
  const int w = 64, h = 32;
  auto map = std::make_shared<EquirectMap>();
  map->width = w;
  map->height = h;
  map->texels.assign(w * h, Rgb{1, 1, 1});
  // Column 0 and 63 straddle north; use the texel whose centre is at azimuth +2.8125°.
  const int i = 0, j = 8;
  map->texels[j * w + i] = {500, 500, 500};
  const Vec3 bright = equirect_texel_direction(w, h, i, j);
  const HorizontalAngles a = world_to_horizontal(bright);
  EXPECT_NEAR(a.azimuth_deg, 360.0 * 0.5 / w, 1e-9);
  const Environment r0 = make_map_environment(map, 0.0, 1.0);
  const Environment r90 = make_map_environment(map, 90.0, 1.0);
  const Environment r180 = make_map_environment(map, 180.0, 1.0);
  const Vec3 east = horizontal_to_world(a.azimuth_deg + 90, a.altitude_deg);
  const Vec3 south = horizontal_to_world(a.azimuth_deg + 180, a.altitude_deg);
  EXPECT_EQ(r0.radiance(bright).g, 500);
  EXPECT_EQ(r90.radiance(bright).g, 1);
  EXPECT_EQ(r90.radiance(east).g, 500);
  EXPECT_GT(east.x, 0.7);  // east is +x
  EXPECT_EQ(r180.radiance(south).g, 500);
  EXPECT_GT(south.z, 0.7);  // south is +z
  // The cubemap puts the texel's energy where radiance() says it is.
  const int n = 8;
  const std::vector<Rgb> cube = environment_cubemap(r90, n);
  const CubemapTexel t = cubemap_texel(n, east);
  EXPECT_GT(cube[cubemap_texel_index(n, t)].g, 5.0);
  EXPECT_NEAR(cube[cubemap_texel_index(n, cubemap_texel(n, bright))].g, 1.0, 0.05);
}

// SH of a map turned by 90° equals the SH of the same map with its columns shifted a quarter.
TEST(Environment, MapShFollowsRotation) {
  const int w = 64, h = 32;
  const auto map = test_map(w, h);
  auto shifted = std::make_shared<EquirectMap>(*map);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) shifted->texels[j * w + (i + w / 4) % w] = map->texels[j * w + i];
  }
  const std::vector<Rgb> a = environment_sh(make_map_environment(map, 90.0, 1.5), 6);
  const std::vector<Rgb> b = environment_sh(make_map_environment(shifted, 0.0, 1.5), 6);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].r, b[k].r, 1e-9 * std::abs(a[0].r));
    EXPECT_NEAR(a[k].b, b[k].b, 1e-9 * std::abs(a[0].b));
  }
  // c00 is the integral.
  const Environment env = make_map_environment(map, 90.0, 1.5);
  EXPECT_NEAR(a[0].g * std::sqrt(4 * kPi), environment_integral(env).g, 1e-9 * a[0].g);
  // And the map's own sh_project_equirect agrees without rotation.
  const std::vector<Rgb> c = sh_project_equirect(6, w, h, std::span<const Rgb>(map->texels));
  const std::vector<Rgb> d = environment_sh(make_map_environment(map, 0.0, 1.0), 6);
  for (std::size_t k = 0; k < c.size(); ++k) EXPECT_NEAR(c[k].g, d[k].g, 1e-9 * c[0].g);
}

TEST(Environment, SkyFromSpecWithPlaceAndTime) {
  EnvironmentSpec spec;
  spec.type = EnvironmentType::kCieSky;
  spec.sky_type = 12;
  spec.scaling = SkyScaling::kHorizontalIlluminance;
  spec.scaling_value = 15000;
  spec.sun_illuminance = 80000;
  spec.sun.placement = SunPlacement::kPlaceAndTime;
  spec.sun.latitude_deg = 51.4779;
  spec.sun.longitude_deg = -0.0015;
  spec.sun.utc_offset_hours = 1.0;  // BST
  spec.sun.local_time = {2021, 6, 21, 13, 0, 0};
  const Environment env = make_environment(spec);
  ASSERT_TRUE(env.sun().has_value());
  const HorizontalAngles a = world_to_horizontal(env.sun()->direction);
  EXPECT_NEAR(a.altitude_deg, 90 - 28.0444, 0.01);  // PyEphem, see sun_position_test.cpp
  EXPECT_NEAR(a.azimuth_deg, 179.0926, 0.02);
  EXPECT_NEAR(env.sky.sky_horizontal_illuminance, 15000, 1e-9);
  EXPECT_GT(env.radiance(env.sun()->direction).g, 1e9);
  // A map spec without its image is a programming error.
  EnvironmentSpec map_spec;
  map_spec.type = EnvironmentType::kMap;
  EXPECT_THROW(make_environment(map_spec), std::invalid_argument);
}

// A Perez spec is the Perez sky of its record, with the sun of its place and time and the
// extraterrestrial irradiance of its date.
TEST(Environment, PerezSkyFromSpec) {
  EnvironmentSpec spec;
  spec.type = EnvironmentType::kPerezSky;
  spec.direct_normal_irradiance = 600;
  spec.diffuse_horizontal_irradiance = 150;
  spec.dew_point_c = 9.0;
  spec.ground_albedo = 0.25;
  spec.sun.placement = SunPlacement::kPlaceAndTime;
  spec.sun.latitude_deg = 51.4779;
  spec.sun.longitude_deg = -0.0015;
  spec.sun.utc_offset_hours = 1.0;
  spec.sun.local_time = {2021, 6, 21, 13, 0, 0};
  const Environment env = make_environment(spec);
  const Vec3 sun = sun_direction(spec.sun);
  const SkyModel expected = make_perez_sky({600, 150, 9.0, 172}, sun, 0.25);
  ASSERT_EQ(env.kind, EnvironmentKind::kSky);
  EXPECT_EQ(env.sky.formula, SkyFormula::kPerez);
  EXPECT_DOUBLE_EQ(env.sky.sky_horizontal_illuminance, expected.sky_horizontal_illuminance);
  EXPECT_DOUBLE_EQ(env.sky.ground_luminance, expected.ground_luminance);
  ASSERT_TRUE(env.sun().has_value());
  EXPECT_DOUBLE_EQ(env.sun()->normal_illuminance, expected.sun->normal_illuminance);
  // Another day of the year changes Δ and so the efficacy.
  const SkyModel january = make_perez_sky({600, 150, 9.0, 1}, sun, 0.25);
  EXPECT_NE(env.sky.sky_horizontal_illuminance, january.sky_horizontal_illuminance);
  // The sun below the horizon: no disc, the dome as the record says.
  spec.sun.local_time = {2021, 6, 21, 23, 0, 0};
  const Environment night = make_environment(spec);
  EXPECT_FALSE(night.sun().has_value());
  EXPECT_GT(night.sky.sky_horizontal_illuminance, 0);
}

}  // namespace
}  // namespace relight
