// A top-level environment and --max-bounces in the reference path tracer against
// closed forms: an open floor under a uniform environment (πL above it, πρL looking down at
// it, each counted once by next-event estimation and escaping continuations together; only
// the direct part with --max-bounces 1), a map with one small bright source (its closed form
// from few samples, thanks to the environment's sampler; a box's shadow where the source is
// hidden), and a closed sphere's interreflection series cut after N terms.
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "light/environment.h"
#include "material/metallic_roughness.h"
#include "math/equirect.h"
#include "reference/reference_tracer.h"
#include "scene/scene_loader.h"
#include "support/scene_json.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

using nlohmann::json;

// The reference sensors of `document`, lit by `environment` when given (else by the scene's
// own top-level environment, if any).
std::vector<Rgb> trace_sensors(const json& document, int spp, int max_bounces = 0,
                               std::optional<Environment> environment = std::nullopt) {
  const Scene scene = scene_from_json(document, "open.json");
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  ReferenceScene ref = make_reference_scene(scene, mesh, traced, luminaires);
  if (!environment && scene.environment) environment = make_environment(*scene.environment);
  if (environment) light_with_environment(ref, std::move(*environment));
  ReferenceSettings settings;
  settings.spp = spp;
  settings.seed = 5;
  settings.progress = false;
  settings.max_bounces = max_bounces;
  return reference_sensor_illuminance(scene, ref, settings);
}

constexpr double kLuminance = 1000;  // cd/m²
constexpr int kOpenSpp = 65536;

// A 200 m floor of albedo 0.5 under a uniform environment; sensors on it facing up and just
// above it facing down.
json open_floor() {
  return {
      {"materials", {{"floor", {{"albedo", {0.5, 0.5, 0.5}}}}}},
      {"geometry", {testing::quad({-100, 0, -100}, {0, 0, 200}, {200, 0, 0}, "floor")}},
      {"environment", {{"type", "uniform"}, {"luminance", kLuminance}}},
      {"sensors",
       {{{"name", "up"}, {"points", {{0, 0, 0}, {3, 0, -2}}}, {"normal", {0, 1, 0}}},
        {{"name", "down"}, {"points", {{0, 0.01, 0}, {-1, 0.01, 4}}}, {"normal", {0, -1, 0}}}}}};
}

TEST(ReferenceEnvironment, AnOpenFloorUnderAUniformEnvironmentIsLitOnceAndReflectsOnce) {
  const double up = kPi * kLuminance, down = 0.5 * kPi * kLuminance;
  const std::vector<Rgb> e = trace_sensors(open_floor(), kOpenSpp);
  ASSERT_EQ(e.size(), 4u);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(luminance(e[i]), up, 0.01 * up) << i;
  for (int i = 2; i < 4; ++i) EXPECT_NEAR(luminance(e[i]), down, 0.01 * down) << i;
  // Direct light only: the floor's reflection is one reflection too many for the down sensors.
  const std::vector<Rgb> direct = trace_sensors(open_floor(), 1024, 1);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(luminance(direct[i]), up, 0.01 * up) << i;
  for (int i = 2; i < 4; ++i) EXPECT_LT(luminance(direct[i]), 1e-3 * down) << i;
  std::printf(
      "open floor: up %.1f, down %.1f lx (closed forms %.1f, %.1f); direct only: down "
      "%.3g lx\n",
      luminance(e[0]), luminance(e[2]), up, down, luminance(direct[2]));
}

// The open floor under a CIE clear sky (type 12) of 10,000 lx horizontal illuminance with a
// 60,000 lx sun at 40°: facing up, the sky's 10,000 lx plus the sun's 60,000 · sin 40°.
TEST(ReferenceEnvironment, AnOpenFloorUnderASkyWithASunGetsBoth) {
  json document = open_floor();
  document["environment"] = {{"type", "cie_sky"},
                             {"sky_type", 12},
                             {"horizontal_illuminance", 10000},
                             {"sun", {{"azimuth_deg", 180}, {"altitude_deg", 40}}},
                             {"sun_illuminance", 60000}};
  const std::vector<Rgb> e = trace_sensors(document, 16384);
  const double up = 10000 + 60000 * std::sin(40 * kPi / 180);
  std::printf("sky and sun: up %.0f, %.0f lx (closed form %.0f)\n", luminance(e[0]),
              luminance(e[1]), up);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(luminance(e[i]), up, 0.01 * up) << i;
}

// The same floor made of satin metal (F0 0.8, roughness 0.3): its luminance toward v is L
// times its directional albedo, so the sensor looking down reads π L times the hemispherical
// albedo — next events weighted against the BRDF's continuation, each light counted once.
TEST(ReferenceEnvironment, AGlossyFloorUnderAUniformEnvironmentReflectsItsHemisphericalAlbedo) {
  json document = open_floor();
  document["materials"]["floor"] = {
      {"albedo", {0.8, 0.8, 0.8}}, {"metallic", 1}, {"roughness", 0.3}};
  const std::vector<Rgb> e = trace_sensors(document, kOpenSpp);
  MetallicRoughness m;
  m.albedo = {0.8, 0.8, 0.8};
  m.metallic = 1;
  m.roughness = 0.3;
  const double down = kPi * kLuminance * luminance(hemispherical_albedo(m));
  std::printf("glossy floor: down %.1f, %.1f lx (closed form %.1f)\n", luminance(e[2]),
              luminance(e[3]), down);
  for (int i = 2; i < 4; ++i) EXPECT_NEAR(luminance(e[i]), down, 0.015 * down) << i;
}

// A 1024 × 512 map of 100 cd/m² with a 2 × 2-texel source of 2·10⁶ cd/m² (0.35° texels) 60°
// above the horizon toward +z in the map, turned 90° by the map's rotation.
Environment small_source(double& source_illuminance, Vec3& toward) {
  auto map = std::make_shared<EquirectMap>();
  map->width = 1024;
  map->height = 512;
  map->texels.assign(std::size_t{1024} * 512, Rgb{100, 100, 100});
  const int j0 = 512 / 6 - 1, i0 = 511;  // θ = 30° from the zenith, azimuth +z in the map
  double e = 0;
  for (int j = j0; j < j0 + 2; ++j) {
    for (int i = i0; i < i0 + 2; ++i) {
      map->texels[static_cast<std::size_t>(j) * 1024 + i] = Rgb{2e6, 2e6, 2e6};
      const Vec3 d = equirect_texel_direction(1024, 512, i, j);
      e += (2e6 - 100) * equirect_row_solid_angle(1024, 512, j) * d.y;
    }
  }
  source_illuminance = e;
  toward = MapRotation(90).to_world(equirect_direction(512.0 / 1024, (j0 + 1.0) / 512));
  return make_map_environment(map, 90, 1);
}

TEST(ReferenceEnvironment, ASmallBrightSourceInAMapLightsAndShadowsAsItsClosedForm) {
  double source = 0;
  Vec3 toward;
  const Environment env = small_source(source, toward);
  ASSERT_GT(std::abs(toward.x), 0.4);  // turned from the map's +z by the rotation
  // An open floor and a 0.4 m box standing 1 m from a sensor toward the source: its shadow
  // falls on the sensor at `shadowed`, not on the one at `lit`.
  const Vec3 shadowed{0, 0, 0}, lit{0, 0, 3};
  const Vec3 c = shadowed + toward * (0.6 / toward.y);  // the box's centre, 0.6 m up
  json document = {
      {"materials", {{"floor", {{"albedo", {0, 0, 0}}}}, {"box", {{"albedo", {0, 0, 0}}}}}},
      {"geometry",
       {testing::quad({-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, "floor"),
        testing::box(c - Vec3{0.2, 0.2, 0.2}, c + Vec3{0.2, 0.2, 0.2}, "box")}},
      {"sensors",
       {{{"name", "floor"},
         {"points", {{shadowed.x, shadowed.y, shadowed.z}, {lit.x, lit.y, lit.z}}},
         {"normal", {0, 1, 0}}}}}};
  // 16,384 samples: a sample draws the source with probability 0.19 (its share of the map's
  // flux), so its part is binomial, 2.1 lx (0.5 %) of noise.
  const std::vector<Rgb> e = trace_sensors(document, 16384, 0, env);
  ASSERT_EQ(e.size(), 2u);
  // The lit sensor: πL of the uniform part less what the black box hides of it (under 1 %),
  // plus the source.
  const double uniform = kPi * 100, expected = uniform + source;
  std::printf("small source: lit %.1f lx (closed form %.1f, the source %.1f), shadowed %.1f lx\n",
              luminance(e[1]), expected, source, luminance(e[0]));
  EXPECT_NEAR(luminance(e[1]), expected, 0.02 * expected);
  EXPECT_LT(luminance(e[0]), uniform);        // the source hidden
  EXPECT_GT(luminance(e[0]), 0.8 * uniform);  // the box hides little of the rest
}

TEST(ReferenceEnvironment, MaxBouncesCutsAClosedSpheresSeriesAfterNTerms) {
  const double rho = 0.6, radius = 2.0, intensity = 100.0, r = radius * 0.999;
  const json scene =
      testing::closed_sphere(rho, radius, intensity,
                             {{{"name", "wall"}, {"points", {{r, 0, 0}}}, {"normal", {-1, 0, 0}}}});
  // E = E_d (1 + ρ + … + ρ^(N−1)) with E_d = I / r².
  for (const int n : {1, 2, 3}) {
    const std::vector<Rgb> e = trace_sensors(scene, 4096, n);
    double series = 0;
    for (int k = 0; k < n; ++k) series += std::pow(rho, k);
    const double expected = intensity / (r * r) * series;
    std::printf("closed sphere, --max-bounces %d: %.3f lx (closed form %.3f)\n", n, luminance(e[0]),
                expected);
    EXPECT_NEAR(luminance(e[0]), expected, 0.02 * expected) << n;
  }
}

}  // namespace
}  // namespace relight
