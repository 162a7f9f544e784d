// Daylight in the reference path tracer against closed forms: a black room lit through a
// skylight or a south window (E = L·π·F, tests/support/daylight_room.h), a constant map
// equal to a uniform environment, the sun patch (E_sun·cos θ inside, sky only outside), an
// overhang outside the window (backward occlusion), two portals adding up, reflected
// daylight counted once, and camera rays that look out through a portal.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "light/environment.h"
#include "light/luminaire_frame.h"
#include "light/sky_model.h"
#include "scene/camera.h"
#include "reference/reference_tracer.h"
#include "scene/scene_loader.h"
#include "support/daylight_room.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

using nlohmann::json;
using testing::parallel_rect_factor;
using testing::perpendicular_rect_factor;
using testing::Rect;
using testing::WindowRoom;

constexpr int kSpp = 16384;
constexpr double kLuminance = 1000;  // cd/m²

// The reference sensors of `document` with the given environments, one per portal.
std::vector<Rgb> trace_sensors(const json& document, std::vector<Environment> environments,
                               int spp = kSpp) {
  const Scene scene = scene_from_json(document, "daylight.json");
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  const ReferenceScene ref =
      make_reference_scene(scene, mesh, traced, luminaires, std::move(environments));
  ReferenceSettings settings;
  settings.spp = spp;
  settings.seed = 11;
  settings.progress = false;
  return reference_sensor_illuminance(scene, ref, settings);
}

json floor_sensors(const std::vector<Vec3>& points) {
  json p = json::array();
  for (Vec3 v : points) p.push_back({v.x, v.y, v.z});
  return json::array({{{"name", "floor"}, {"points", p}, {"normal", {0, 1, 0}}}});
}

Environment grey_uniform(double l) {
  return make_uniform_environment({l, l, l});
}

// Room 4 × 3 × 5 m: skylight x ∈ [1.5, 2.5], z ∈ [2, 3.5]; south window (wall z = 5)
// x ∈ [1, 3], y ∈ [0.9, 2.1].
constexpr Rect kSkylight{1.5, 2.5, 2, 3.5};
constexpr Rect kWindow{1, 3, 0.9, 2.1};

WindowRoom skylight_room() {
  WindowRoom room;
  room.skylight = kSkylight;
  return room;
}

WindowRoom window_room() {
  WindowRoom room;
  room.south_window = kWindow;
  return room;
}

const std::vector<Vec3> kSkylightPoints = {{2, 0, 2.75}, {1.5, 0, 2}, {0.6, 0, 1}, {3.5, 0, 4.5}};
const std::vector<Vec3> kWindowPoints = {{2, 0, 4}, {1.2, 0, 3.5}, {3.6, 0, 2}, {2, 0, 1}};

double skylight_factor(Vec3 p, double height = 3) {
  return parallel_rect_factor(kSkylight.u0 - p.x, kSkylight.u1 - p.x, kSkylight.v0 - p.z,
                              kSkylight.v1 - p.z, height);
}

double window_factor(Vec3 p, double depth = 5) {
  return perpendicular_rect_factor(kWindow.u0 - p.x, kWindow.u1 - p.x, kWindow.v0, kWindow.v1,
                                   depth - p.z);
}

TEST(ReferencePortal, SkylightToUniformSkyWithinTwoPercentOfLPiF) {
  json scene = testing::window_room_json(skylight_room());
  scene["sensors"] = floor_sensors(kSkylightPoints);
  const std::vector<Rgb> e = trace_sensors(scene, {grey_uniform(kLuminance)});
  ASSERT_EQ(e.size(), kSkylightPoints.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double expected = kLuminance * kPi * skylight_factor(kSkylightPoints[i]);
    EXPECT_NEAR(luminance(e[i]), expected, 0.02 * expected) << "sensor " << i;
  }
}

TEST(ReferencePortal, WallWindowToUniformSkyWithinTwoPercentOfLPiF) {
  json scene = testing::window_room_json(window_room());
  scene["sensors"] = floor_sensors(kWindowPoints);
  const std::vector<Rgb> e = trace_sensors(scene, {grey_uniform(kLuminance)});
  ASSERT_EQ(e.size(), kWindowPoints.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double expected = kLuminance * kPi * window_factor(kWindowPoints[i]);
    EXPECT_NEAR(luminance(e[i]), expected, 0.02 * expected) << "sensor " << i;
  }
}

TEST(ReferencePortal, ConstantMapMatchesUniformEnvironment) {
  // Texels of L/2 scaled by 2 and turned: the same radiance in every direction.
  auto map = std::make_shared<EquirectMap>();
  map->width = 16;
  map->height = 8;
  map->texels.assign(16 * 8, Rgb{kLuminance / 2, kLuminance / 2, kLuminance / 2});
  json scene = testing::window_room_json(window_room());
  scene["sensors"] = floor_sensors(kWindowPoints);
  const std::vector<Rgb> from_map = trace_sensors(scene, {make_map_environment(map, 37, 2)});
  const std::vector<Rgb> uniform = trace_sensors(scene, {grey_uniform(kLuminance)});
  ASSERT_EQ(from_map.size(), uniform.size());
  for (std::size_t i = 0; i < uniform.size(); ++i) {
    // Same seeds, same radiance: the same estimate.
    EXPECT_NEAR(luminance(from_map[i]), luminance(uniform[i]), 1e-9 * luminance(uniform[i]));
    const double expected = kLuminance * kPi * window_factor(kWindowPoints[i]);
    EXPECT_NEAR(luminance(from_map[i]), expected, 0.02 * expected) << "sensor " << i;
  }
}

// A uniform sky (CIE type 5) of zenith luminance L, black ground, and a sun of normal
// illuminance E_sun from the south (+z) at `altitude_deg`.
Environment sunny_sky(double altitude_deg, double sun_illuminance) {
  const double a = altitude_deg * kPi / 180;
  const Vec3 toward_sun{0, std::sin(a), std::cos(a)};
  return make_sky_environment(
      make_sky_from_zenith_luminance(5, toward_sun, kLuminance, 0, sun_illuminance));
}

TEST(ReferencePortal, SunPatchUnderSkylightGetsSunPlusSkyOutsideOnlySky) {
  // Sun at 60° from the south: the skylight's patch on the floor is x ∈ [1.5, 2.5],
  // z ∈ [2 − 3/tan 60°, 3.5 − 3/tan 60°] = [0.27, 1.77].
  const double e_sun = 80000, altitude = 60;
  const std::vector<Vec3> points = {{2, 0, 1.0}, {1.8, 0, 1.5}, {2, 0, 2.75}, {1, 0, 1.0}};
  const std::vector<bool> sunlit = {true, true, false, false};
  json scene = testing::window_room_json(skylight_room());
  scene["sensors"] = floor_sensors(points);
  const std::vector<Rgb> e = trace_sensors(scene, {sunny_sky(altitude, e_sun)});
  ASSERT_EQ(e.size(), points.size());
  const double sun = e_sun * std::sin(altitude * kPi / 180);  // E_sun · cos θ on the floor
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double sky = kLuminance * kPi * skylight_factor(points[i]);
    const double measured_sky = luminance(e[i]) - (sunlit[i] ? sun : 0.0);
    EXPECT_NEAR(measured_sky, sky, 0.02 * sky) << "sensor " << i;
  }
}

TEST(ReferencePortal, OverhangOutsideTheWindowRemovesTheSkyAndSunItBlocks) {
  // Sun at 45° from the south. Without the overhang a floor point at distance c from the
  // south wall is sunlit for c ∈ [0.9, 2.1]; an overhang at the window head (y = 2.1)
  // projecting 0.6 m shades it where (c + 0.6)·tan 45° > 2.1, i.e. c > 1.5.
  const double e_sun = 100000, altitude = 45, overhang = 0.6;
  const std::vector<Vec3> points = {{2, 0, 3.8}, {2, 0, 3.2}, {1.5, 0, 2.5}};
  const std::vector<bool> sunlit_open = {true, true, false}, sunlit_shaded = {true, false, false};
  json open = testing::window_room_json(window_room());
  open["sensors"] = floor_sensors(points);
  json shaded = open;
  shaded["geometry"].push_back(testing::quad({-20, 2.1, 5}, {0, 0, overhang}, {44, 0, 0}, "room"));
  const std::vector<Rgb> e_open = trace_sensors(open, {sunny_sky(altitude, e_sun)});
  const std::vector<Rgb> e_shaded = trace_sensors(shaded, {sunny_sky(altitude, e_sun)});
  const double sun = e_sun * std::sin(altitude * kPi / 180);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    const double c = 5 - p.z, outer = c + overhang, grow = outer / c;
    // Open: the window. Shaded: what passes under the overhang's outer edge, i.e. the
    // window projected from p onto the plane of that edge, cut at the overhang's height.
    const double sky_open = kLuminance * kPi * window_factor(p);
    const double sky_shaded =
        kLuminance * kPi *
        perpendicular_rect_factor((kWindow.u0 - p.x) * grow, (kWindow.u1 - p.x) * grow,
                                  kWindow.v0 * grow, std::max(kWindow.v0 * grow, kWindow.v1),
                                  outer);
    ASSERT_LT(sky_shaded, 0.9 * sky_open) << "the overhang should block some sky";
    const double measured_open = luminance(e_open[i]) - (sunlit_open[i] ? sun : 0.0);
    const double measured_shaded = luminance(e_shaded[i]) - (sunlit_shaded[i] ? sun : 0.0);
    EXPECT_NEAR(measured_open, sky_open, 0.02 * sky_open) << "sensor " << i;
    EXPECT_NEAR(measured_shaded, sky_shaded, 0.02 * sky_shaded) << "sensor " << i;
  }
}

TEST(ReferencePortal, TwoPortalsWithDifferentEnvironmentsAddUp) {
  // Red light through the skylight, green through the window: each channel is one portal.
  const double red = 2000, green = 500;
  WindowRoom room = window_room();
  room.skylight = kSkylight;
  json scene = testing::window_room_json(room);
  const std::vector<Vec3> points = {{2, 0, 3.2}, {1.5, 0, 2}, {2, 0, 4.2}};
  scene["sensors"] = floor_sensors(points);
  const std::vector<Rgb> e =
      trace_sensors(scene, {make_uniform_environment({red, 0, 0}),  // "skylight" comes first
                            make_uniform_environment({0, green, 0})});
  ASSERT_EQ(e.size(), points.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double r = red * kPi * skylight_factor(points[i]);
    const double g = green * kPi * window_factor(points[i]);
    EXPECT_NEAR(e[i].r, r, 0.02 * r) << "sensor " << i;
    EXPECT_NEAR(e[i].g, g, 0.02 * g) << "sensor " << i;
    EXPECT_EQ(e[i].b, 0.0);
  }
}

TEST(ReferencePortal, ReflectedDaylightIsCountedOnce) {
  // A floor of albedo ρ inside a portal sphere of uniform luminance L: the floor gets πL,
  // so it has luminance ρL and a sensor just above it facing down reads πρL (the sliver of
  // sphere it sees past the floor's edge adds < 1e-4 of that). Counting the floor's daylight
  // by both next-event estimation and escaping continuation rays would give 2πρL.
  const double rho = 0.5;
  const json scene = {
      {"materials",
       {{"floor", {{"albedo", {rho, rho, rho}}}},
        {"glass", {{"albedo", {0, 0, 0}}, {"portal", true}}}}},
      {"geometry",
       {testing::quad({-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, "floor"),
        {{"type", "sphere"},
         {"center", {0, 0, 0}},
         {"radius", 3},
         {"subdivisions", 3},
         {"material", "glass"}}}},
      {"portals",
       {{{"name", "sky"},
         {"material", "glass"},
         {"environment", {{"type", "uniform"}, {"luminance", kLuminance}}}}}},
      {"sensors",
       {{{"name", "up"}, {"points", {{0, 0, 0}, {0.8, 0, -0.6}}}, {"normal", {0, 1, 0}}},
        {{"name", "down"}, {"points", {{0, 0.01, 0}, {0.5, 0.01, 1}}}, {"normal", {0, -1, 0}}}}}};
  // Half of the sphere's area lies below the floor and the floor's hit points spread over
  // it: a noisier estimate than the rooms', hence more samples.
  const std::vector<Rgb> e = trace_sensors(scene, {grey_uniform(kLuminance)}, 1 << 18);
  ASSERT_EQ(e.size(), 4u);
  const double up = kPi * kLuminance, down = rho * kPi * kLuminance;
  EXPECT_NEAR(luminance(e[0]), up, 0.02 * up);
  EXPECT_NEAR(luminance(e[1]), up, 0.02 * up);
  EXPECT_NEAR(luminance(e[2]), down, 0.02 * down);
  EXPECT_NEAR(luminance(e[3]), down, 0.02 * down);
}

TEST(ReferencePortal, CameraLookingOutThroughAPortalSeesTheEnvironment) {
  const json scene_json = testing::window_room_json(skylight_room());
  const Scene scene = scene_from_json(scene_json, "daylight.json");
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  const std::vector<PlacedLuminaire> luminaires;
  const ReferenceScene ref = make_reference_scene(scene, mesh, traced, luminaires,
                                                  {make_uniform_environment({300, 400, 500})});
  ReferenceSettings settings;
  settings.spp = 4;
  settings.progress = false;
  // From under the skylight straight up, a 20° view: every pixel sees the sky.
  Camera up_camera{"up", {2, 1.5, 2.75}, {2, 3, 2.75}, {0, 0, -1}, 20};
  const ReferenceImages up = reference_render(make_pinhole_camera(up_camera, 8, 8), ref, settings);
  for (std::size_t i = 0; i < up.luminance.pixels.size(); ++i) {
    EXPECT_EQ(up.luminance.pixels[i].r, 300);
    EXPECT_EQ(up.luminance.pixels[i].b, 500);
    EXPECT_TRUE(std::isnan(up.illuminance.pixels[i].g));
  }
  // Looking down at the black floor: luminance 0, illuminance that of the skylight.
  Camera down_camera{"down", {2, 1.5, 2.75}, {2, 0, 2.75}, {0, 0, -1}, 5};
  const ReferenceImages down =
      reference_render(make_pinhole_camera(down_camera, 2, 2), ref, settings);
  for (const Rgb& l : down.luminance.pixels) EXPECT_EQ(luminance(l), 0.0);
  for (const Rgb& e : down.illuminance.pixels) EXPECT_GT(e.g, 0.0);
}

}  // namespace
}  // namespace relight
