// The run-time portal shell (sources/portals/shell.h, shell_environment.h, shell_exterior.h,
// shell_frost.h): the base shell against light/environment.h, exact tint, flux-preserving frost
// and its spread, exterior walls against the closed-form Lambertian radiance, sun occlusion by
// a building, and the SH representation against the cubemap it is projected from.
#include "sources/portals/shell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "light/environment_irradiance.h"
#include "light/sky_model.h"
#include "math/cubemap.h"
#include "math/sh.h"
#include "sources/portals/shell_frost.h"

namespace relight {
namespace {

double rel_diff(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

double max_rel_diff(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, max_component(a[i]));
    diff = std::max(
        {diff, std::abs(a[i].r - b[i].r), std::abs(a[i].g - b[i].g), std::abs(a[i].b - b[i].b)});
  }
  return diff / scale;
}

// Σ L·c·Ω over the texels with c = ω·outward > 0 at the centre, per channel.
Rgb front_flux(int n, Vec3 outward, const std::vector<Rgb>& cubemap) {
  Rgb sum;
  for (std::size_t k = 0; k < cubemap.size(); ++k) {
    const CubemapTexel t = cubemap_texel_from_index(n, k);
    const double c = dot(cubemap_texel_direction(n, t), outward);
    if (c > 0) sum += cubemap[k] * (c * cubemap_texel_solid_angle(n, t.i, t.j));
  }
  return sum;
}

Vec3 horizontal(double azimuth_deg, double altitude_deg) {
  // Azimuth from north (−z) toward east (+x).
  const double a = radians(azimuth_deg), h = radians(altitude_deg);
  return {std::cos(h) * std::sin(a), std::sin(h), -std::cos(h) * std::cos(a)};
}

Environment clear_sky(Vec3 sun) {
  return make_sky_environment(make_sky_from_horizontal_illuminance(12, sun, 15000, 0.2, 80000));
}

// A rectangle (two triangles) a + s·e1 + t·e2, s, t ∈ [0, 1].
ExteriorObject quad(Vec3 a, Vec3 e1, Vec3 e2, Rgb albedo) {
  ExteriorObject o;
  o.positions = {a, a + e1, a + e1 + e2, a + e2};
  o.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
  o.albedo = albedo;
  return o;
}

const PortalFrame kEastWindow{{0, 1.5, 0}, {1, 0, 0}};

TEST(Shell, UniformEnvironmentIsExactInCubemapAndSh) {
  const Rgb l{2, 3, 4};
  const Environment env = make_uniform_environment(l);
  ShellInputs in;
  in.environment = &env;
  const Shell shell = render_shell(in, kEastWindow, 32, 6);
  ASSERT_EQ(shell.cubemap.size(), cubemap_texel_count(32));
  ASSERT_EQ(shell.sh.size(), 36u);
  for (const Rgb& t : shell.cubemap) {
    EXPECT_EQ(t.r, 2.0);
    EXPECT_EQ(t.g, 3.0);
    EXPECT_EQ(t.b, 4.0);
  }
  const double c00 = std::sqrt(4 * kPi);
  EXPECT_LT(rel_diff(shell.sh[0].r, c00 * 2), 1e-12);
  EXPECT_LT(rel_diff(shell.sh[0].g, c00 * 3), 1e-12);
  EXPECT_LT(rel_diff(shell.sh[0].b, c00 * 4), 1e-12);
  for (std::size_t k = 1; k < shell.sh.size(); ++k) EXPECT_LT(max_component(shell.sh[k]), 1e-12);
  EXPECT_FALSE(shell.sun_in_shell);
}

TEST(Shell, BaseShellIsTheEnvironmentCubemapWithTheSunDeposited) {
  const Environment env = clear_sky(horizontal(100, 35));
  ShellInputs in;
  in.environment = &env;
  const Shell shell = render_shell(in, kEastWindow, 16, 6);
  EXPECT_TRUE(shell.sun_in_shell);
  EXPECT_LT(max_rel_diff(environment_cubemap(env, 16), shell.cubemap), 1e-14);
  // The sun-less copy differs only in the sun's texel, by ∫_disc L dω / Ω.
  const std::vector<Rgb> continuous = environment_cubemap(environment_without_sun(env), 16);
  const CubemapTexel st = cubemap_texel(16, env.sun()->direction);
  const std::size_t si = cubemap_texel_index(16, st);
  for (std::size_t k = 0; k < continuous.size(); ++k) {
    if (k == si) continue;
    EXPECT_EQ(continuous[k].g, shell.cubemap[k].g);
  }
  EXPECT_LT(rel_diff(shell.cubemap[si].g - continuous[si].g,
                     env.sun()->integrated_luminance() / cubemap_texel_solid_angle(16, st.i, st.j)),
            1e-12);
}

// Without the sun disc (the run time traces the sun itself behind clear glass) the
// shell is exactly the environment's continuous part: its cubemap and its SH hold no sun.
TEST(Shell, WithoutTheSunDiscTheShellIsTheSkyAlone) {
  const Environment env = clear_sky(horizontal(100, 35));
  ShellInputs in;
  in.environment = &env;
  in.sun_disc = false;
  const Shell shell = render_shell(in, kEastWindow, 16, 6);
  EXPECT_FALSE(shell.sun_in_shell);
  EXPECT_LT(max_rel_diff(environment_cubemap(environment_without_sun(env), 16), shell.cubemap),
            1e-14);
  ShellInputs sky_only = in;
  const Environment continuous = environment_without_sun(env);
  sky_only.environment = &continuous;
  const Shell reference = render_shell(sky_only, kEastWindow, 16, 6);
  for (std::size_t k = 0; k < shell.sh.size(); ++k)
    EXPECT_EQ(shell.sh[k].g, reference.sh[k].g) << k;
}

TEST(Shell, TintScalesCubemapExactlyAndSh) {
  const Environment env = clear_sky(horizontal(120, 30));
  ShellInputs in;
  in.environment = &env;
  in.frost_deg = 5;
  const Shell plain = render_shell(in, kEastWindow, 16, 6);
  in.tint = {0.5, 0.8, 0.3};
  const Shell tinted = render_shell(in, kEastWindow, 16, 6);
  for (std::size_t k = 0; k < plain.cubemap.size(); ++k) {
    EXPECT_EQ(tinted.cubemap[k].r, plain.cubemap[k].r * 0.5);
    EXPECT_EQ(tinted.cubemap[k].g, plain.cubemap[k].g * 0.8);
    EXPECT_EQ(tinted.cubemap[k].b, plain.cubemap[k].b * 0.3);
  }
  std::vector<Rgb> scaled(plain.sh.size());
  for (std::size_t k = 0; k < scaled.size(); ++k) scaled[k] = plain.sh[k] * in.tint;
  EXPECT_LT(max_rel_diff(scaled, tinted.sh), 1e-13);
}

TEST(Shell, ShIsTheProjectionOfTheFinalCubemap) {
  const Environment env = clear_sky(horizontal(90, 25));
  const ExteriorObject building = quad({8, -2, -3}, {0, 0, 6}, {0, 12, 0}, {0.4, 0.35, 0.3});
  ShellInputs in;
  in.environment = &env;
  in.frost_deg = 4;
  in.tint = {0.9, 0.95, 1.0};
  in.exterior = std::span<const ExteriorObject>(&building, 1);
  const Shell shell = render_shell(in, kEastWindow, 32, 6);
  const std::vector<Rgb> projected = sh_project_cubemap(6, 32, std::span<const Rgb>(shell.cubemap));
  ASSERT_EQ(projected.size(), shell.sh.size());
  for (std::size_t k = 0; k < projected.size(); ++k) {
    EXPECT_EQ(projected[k].r, shell.sh[k].r);
    EXPECT_EQ(projected[k].b, shell.sh[k].b);
  }
  // And the SH reconstructs the cubemap's band-limited content: a sun-less overcast sky
  // (smooth) through a clear window, l < 6, against the cubemap at its texel centres.
  const Environment overcast =
      make_sky_environment(make_sky_from_horizontal_illuminance(1, {0, 1, 0}, 10000, 0.2, 0));
  ShellInputs oc;
  oc.environment = &overcast;
  const Shell smooth = render_shell(oc, kEastWindow, 32, 6);
  const std::vector<Rgb> exact = environment_sh(overcast, 6);
  double worst = 0;
  for (std::size_t k = 0; k < exact.size(); ++k)
    worst = std::max(worst, std::abs(exact[k].g - smooth.sh[k].g));
  EXPECT_LT(worst / exact[0].g, 2e-3) << "cubemap vs exact SH, relative to c00: " << worst;
  std::cout << "overcast sky, SH of the N = 32 shell vs environment_sh, l < 6: worst |Δc| / c00 "
            << worst / exact[0].g << '\n';
}

TEST(ShellFrost, ZeroWidthIsTheIdentity) {
  const Environment env = clear_sky(horizontal(100, 35));
  std::vector<Rgb> cubemap = environment_cubemap(env, 16);
  const std::vector<Rgb> before = cubemap;
  frost_cubemap(16, {1, 0, 0}, 0.0, cubemap);
  for (std::size_t k = 0; k < cubemap.size(); ++k) EXPECT_EQ(cubemap[k].g, before[k].g);
  ShellInputs in;
  in.environment = &env;
  EXPECT_LT(max_rel_diff(render_shell(in, kEastWindow, 16, 6).cubemap, before), 1e-15);
}

TEST(ShellFrost, PreservesFluxThroughTheWindowAndLeavesTheBackAlone) {
  const Environment env = clear_sky(horizontal(70, 40));
  const Vec3 outward = normalize(Vec3{1, 0.2, -0.4});
  double worst = 0;
  for (const int n : {16, 32}) {
    const std::vector<Rgb> before = environment_cubemap(env, n);
    const Rgb flux = front_flux(n, outward, before);
    for (const double deg : {0.5, 2.0, 5.0, 15.0, 40.0, 120.0}) {
      std::vector<Rgb> after = before;
      FrostPlan plan;
      make_frost_plan(n, outward, deg, plan);
      std::vector<Rgb> scratch;
      apply_frost(plan, after, scratch);
      const Rgb blurred = front_flux(n, outward, after);
      worst = std::max({worst, rel_diff(blurred.r, flux.r), rel_diff(blurred.b, flux.b)});
      EXPECT_LT(rel_diff(blurred.r, flux.r), 1e-9) << "N " << n << " frost " << deg;
      EXPECT_LT(rel_diff(blurred.b, flux.b), 1e-9) << "N " << n << " frost " << deg;
      for (std::size_t k = 0; k < after.size(); ++k) {
        const CubemapTexel t = cubemap_texel_from_index(n, k);
        // Front/back as the plan classifies them (its outward is normalised once more, which
        // can flip the sign of c for a texel centre lying on the window plane, where c ≈ 1e-17).
        if (!(dot(cubemap_texel_direction(n, t), plan.outward) > 0)) {
          EXPECT_EQ(after[k].g, before[k].g);
        }
      }
    }
  }
  std::cout << "frost flux, worst relative change over N 16, 32 and 0.5°..120°: " << worst << '\n';
}

// The kernel recomputed at each application (a plan over its storage budget) gives the same
// blur, bit for bit, as the stored one.
TEST(ShellFrost, StoredAndRecomputedKernelsAgree) {
  const Environment env = clear_sky(horizontal(70, 40));
  const Vec3 outward{0.6, 0, 0.8};
  for (const double deg : {3.0, 20.0}) {
    FrostPlan stored, recomputed;
    make_frost_plan(16, outward, deg, stored);
    make_frost_plan(16, outward, deg, recomputed, 0);
    EXPECT_FALSE(stored.kernel.empty());
    EXPECT_TRUE(recomputed.kernel.empty());
    std::vector<Rgb> a = environment_cubemap(env, 16), b = a, scratch;
    apply_frost(stored, a, scratch);
    apply_frost(recomputed, b, scratch);
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].g, b[k].g);
  }
}

// A cubemap holding only the sun disc, in front of a window facing it.
TEST(ShellFrost, BlursTheSunMoreForWiderFrost) {
  const int n = 32;
  const Vec3 outward{1, 0, 0};
  const SunDisc sun = make_sun_disc(normalize(Vec3{1, 0.35, 0.2}), 100000);
  std::vector<Rgb> sharp(cubemap_texel_count(n));
  deposit_sun(sun, n, sharp);
  const CubemapTexel st = cubemap_texel(n, sun.direction);
  const std::size_t si = cubemap_texel_index(n, st);
  const CubemapTexel neighbour{st.face, st.i + 1, st.j};
  const std::size_t ni = cubemap_texel_index(n, neighbour);
  double previous_spread = 0;
  for (const double deg : {3.0, 6.0, 12.0}) {
    std::vector<Rgb> soft = sharp;
    frost_cubemap(n, outward, deg, soft);
    EXPECT_LT(soft[si].g, 0.2 * sharp[si].g) << deg;
    EXPECT_GT(soft[ni].g, 0.1 * soft[si].g) << deg;  // ~2.8° texel pitch at N = 32
    // Flux-weighted RMS angle from the sun: √2·σ for the vMF kernel on a tangent plane.
    double w_sum = 0, w_theta2 = 0;
    for (std::size_t k = 0; k < soft.size(); ++k) {
      const CubemapTexel t = cubemap_texel_from_index(n, k);
      const Vec3 d = cubemap_texel_direction(n, t);
      const double c = dot(d, outward);
      if (c <= 0) continue;
      const double w = soft[k].g * c * cubemap_texel_solid_angle(n, t.i, t.j);
      const double theta = std::acos(std::clamp(dot(d, sun.direction), -1.0, 1.0));
      w_sum += w;
      w_theta2 += w * theta * theta;
    }
    const double spread = degrees(std::sqrt(w_theta2 / w_sum));
    EXPECT_NEAR(spread / (std::sqrt(2.0) * deg), 1.0, 0.2) << "frost " << deg;
    EXPECT_GT(spread, previous_spread * 1.5);
    previous_spread = spread;
    std::cout << "frost " << deg << "°: sun texel " << soft[si].g / sharp[si].g
              << " of sharp, neighbour/sun " << soft[ni].g / soft[si].g << ", RMS spread " << spread
              << "°\n";
  }
}

// A wall across the street facing the window (west), lit by a low western sun under a uniform
// sky (CIE type 5) with a Lambertian ground: every texel of the lower half of the +X face sees
// it, with L = ρ/π·(E_sun·cos h + π(Lz + Lg)/2) (vertical wall: half sky, half ground; the R&H
// 9-term irradiance is exact for this step-shaped environment since the odd bands l ≥ 3 of
// the clamped cosine vanish).
TEST(ShellExterior, WallReplacesTheLowerHalfWithItsShadedRadiance) {
  const double h = 30;
  const Vec3 sun_dir = horizontal(270, h);
  const Environment env =
      make_sky_environment(make_sky_from_zenith_luminance(5, sun_dir, 4000, 0.25, 60000));
  const double lz = env.sky.zenith_luminance, lg = env.sky.ground_luminance;
  const Rgb albedo{0.6, 0.5, 0.4};
  const Vec3 c = kEastWindow.centre;
  const ExteriorObject wall = quad(c + Vec3{5, -200, -200}, {0, 0, 400}, {0, 200, 0}, albedo);
  ShellInputs in;
  in.environment = &env;
  in.exterior = std::span<const ExteriorObject>(&wall, 1);
  const int n = 32;
  const Shell shell = render_shell(in, kEastWindow, n, 6);
  const std::vector<Rgb> sky = environment_cubemap(env, n);
  const double e = 60000 * std::cos(radians(h)) + kPi * (lz + lg) / 2;
  double worst = 0, worst_sky = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t k = cubemap_texel_index(n, {kPosX, i, j});
      if (j >= n / 2) {  // y < 0: the wall
        worst = std::max({worst, rel_diff(shell.cubemap[k].r, albedo.r / kPi * e),
                          rel_diff(shell.cubemap[k].b, albedo.b / kPi * e)});
      } else {  // y > 0: open sky
        worst_sky = std::max(worst_sky, rel_diff(shell.cubemap[k].g, sky[k].g));
      }
    }
  EXPECT_LT(worst, 1e-6) << "wall texels vs ρ/π·E";
  EXPECT_EQ(worst_sky, 0.0);
  EXPECT_TRUE(shell.sun_in_shell);  // the sun is behind the window, over the house
  EXPECT_GE(shell.exterior_texels, static_cast<std::size_t>(n * n / 2));
  std::cout << "wall radiance " << albedo.g / kPi * e << " cd/m², worst relative error " << worst
            << '\n';
}

TEST(ShellExterior, BuildingBetweenWindowAndSunRemovesTheSun) {
  const Vec3 sun_dir = horizontal(90, 20);  // due east, in front of the window
  const Environment env = clear_sky(sun_dir);
  const int n = 32;
  const Vec3 c = kEastWindow.centre;
  // A building face 10 m east, 25 m high, 20 m wide: the sun ray meets it 3.6 m above the
  // window. The same face moved 60 m south leaves the sun free.
  const ExteriorObject blocking =
      quad(c + Vec3{10, -5, -10}, {0, 0, 20}, {0, 25, 0}, {0.3, 0.3, 0.3});
  const ExteriorObject aside = quad(c + Vec3{10, -5, 50}, {0, 0, 20}, {0, 25, 0}, {0.3, 0.3, 0.3});
  ShellInputs in;
  in.environment = &env;
  const double deposit =
      env.sun()->integrated_luminance() /
      cubemap_texel_solid_angle(n, cubemap_texel(n, sun_dir).i, cubemap_texel(n, sun_dir).j);
  const std::size_t si = cubemap_texel_index(n, cubemap_texel(n, sun_dir));

  in.exterior = std::span<const ExteriorObject>(&blocking, 1);
  const Shell shadowed = render_shell(in, kEastWindow, n, 6);
  EXPECT_FALSE(shadowed.sun_in_shell);
  EXPECT_LT(shadowed.cubemap[si].g, 1e-4 * deposit);

  in.exterior = std::span<const ExteriorObject>(&aside, 1);
  const Shell sunny = render_shell(in, kEastWindow, n, 6);
  EXPECT_TRUE(sunny.sun_in_shell);
  EXPECT_GT(sunny.cubemap[si].g, deposit);
  // The flux through the window drops by at least the sun's share: E_sun,n·cos(angle to the
  // normal) in lux (the disc's Σ L·c·Ω), to within the disc's extent.
  const double lost =
      front_flux(n, {1, 0, 0}, sunny.cubemap).g - front_flux(n, {1, 0, 0}, shadowed.cubemap).g;
  EXPECT_GT(lost, 0.99 * 80000 * dot(sun_dir, Vec3{1, 0, 0}) *
                      (env.sun()->integrated_luminance() / env.sun()->normal_illuminance));
}

TEST(Shell, WorkspaceReuseMatchesOneShotRendering) {
  const ExteriorObject building = quad({8, -2, -3}, {0, 0, 6}, {0, 12, 0}, {0.4, 0.35, 0.3});
  Shell shell;
  ShellWorkspace workspace;
  for (const double az : {80.0, 100.0, 130.0}) {
    const Environment env = clear_sky(horizontal(az, 30));
    ShellInputs in;
    in.environment = &env;
    in.frost_deg = 6;
    in.exterior = std::span<const ExteriorObject>(&building, 1);
    render_shell(in, kEastWindow, 16, 6, shell, workspace);
    const Shell fresh = render_shell(in, kEastWindow, 16, 6);
    EXPECT_LT(max_rel_diff(fresh.cubemap, shell.cubemap), 1e-15) << az;
    EXPECT_LT(max_rel_diff(fresh.sh, shell.sh), 1e-15) << az;
  }
}

TEST(Shell, RejectsBadInputs) {
  const Environment env = make_uniform_environment({1, 1, 1});
  ShellInputs in;
  EXPECT_THROW(render_shell(in, kEastWindow), std::invalid_argument);
  in.environment = &env;
  EXPECT_THROW(render_shell(in, {{0, 0, 0}, {0, 0, 0}}), std::invalid_argument);
  in.frost_deg = -1;
  EXPECT_THROW(render_shell(in, kEastWindow), std::invalid_argument);
  in.frost_deg = 0;
  in.tint = {-1, 1, 1};
  EXPECT_THROW(render_shell(in, kEastWindow), std::invalid_argument);
  in.tint = {1, 1, 1};
  ExteriorObject bad = quad({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0.5});
  bad.triangles.push_back({0, 1, 7});
  in.exterior = std::span<const ExteriorObject>(&bad, 1);
  EXPECT_THROW(render_shell(in, kEastWindow), std::invalid_argument);
}

}  // namespace
}  // namespace relight
