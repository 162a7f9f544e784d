// The project's site through the whole run time (scene/environment_spec.h "site"): a black
// 4 × 3 × 5 m room under a skylight, lit by a sun disc alone. True north at the scene's −z puts
// a south sun's patch on the north wall; a lighting state's site turning north 90° clockwise puts
// it on the east wall (+x). The lit sensor reads E_sun·cos 40° within 2%, the other nothing.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/daylight_harness.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

using nlohmann::json;

constexpr double kSunIlluminance = 80000;  // lx normal to the sun
constexpr double kAltitudeDeg = 40;

json skylit_room() {
  testing::WindowRoom room;
  room.skylight = testing::kSkylight;
  json scene = testing::window_room_json(room);
  scene["site"] = {{"latitude", 48.1}, {"longitude", 11.6}, {"utc_offset", 1}};
  scene["portals"][0]["environment"] = {
      {"type", "cie_sky"},
      {"sky_type", 12},
      {"horizontal_illuminance", 0},
      {"sun", {{"azimuth_deg", 180}, {"altitude_deg", kAltitudeDeg}}},
      {"sun_illuminance", kSunIlluminance}};
  // Points where a sun 40° high in the scene's south (+z), or west (−x), shines through the
  // skylight (x 1.5..2.5, z 2..3.5 at y = 3), 2 cm off the wall.
  scene["sensors"] = {
      {{"name", "north wall"}, {"points", {{2, 0.7, 0.02}}}, {"normal", {0, 0, 1}}},
      {{"name", "east wall"}, {"points", {{3.98, 1.3, 2.75}}}, {"normal", {-1, 0, 0}}}};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 16}, {"sensor_gather_rays", 16}};
  return scene;
}

TEST(SiteNorth, NinetyDegreesTurnsASouthSunPatchFromTheNorthWallOntoTheEastWall) {
  const testing::Daylight day(skylit_room());
  const double lit = kSunIlluminance * std::cos(kAltitudeDeg * kPi / 180);
  const auto lux = [](const Rgb& e) { return luminance(e); };

  const std::vector<Rgb> north_up = day.sensors();
  std::printf("north 0°: north wall %.0f lx, east wall %.1f lx (expected %.0f)\n", lux(north_up[0]),
              lux(north_up[1]), lit);
  EXPECT_NEAR(lux(north_up[0]), lit, 0.02 * lit);
  EXPECT_LT(lux(north_up[1]), 1.0);

  const std::vector<Rgb> turned = day.sensors(
      {{"site", {{"latitude", 48.1}, {"longitude", 11.6}, {"utc_offset", 1}, {"north_deg", 90}}}});
  std::printf("north 90°: north wall %.1f lx, east wall %.0f lx\n", lux(turned[0]), lux(turned[1]));
  EXPECT_LT(lux(turned[0]), 1.0);
  EXPECT_NEAR(lux(turned[1]), lit, 0.02 * lit);
}

}  // namespace
}  // namespace relight
