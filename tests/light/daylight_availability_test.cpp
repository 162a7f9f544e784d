// The daylight available by solar altitude (light/daylight_availability.h): the Ineichen & Perez
// 2002 clear sky, the Kasten & Czeplak cloud cover and the Perez 1990 efficacies, each against the
// published formulas evaluated by hand (a separate script of the formulas as printed, values
// below) within 2%; the sky a scene builds from them; nothing at night; the site's north turning
// the sun.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/input_error.h"
#include "light/daylight_availability.h"
#include "light/environment.h"
#include "light/sun_position.h"
#include "scene/environment_spec.h"
#include "scene/json_node.h"

namespace relight {
namespace {

constexpr double kTolerance = 0.02;  // the acceptance: within 2% of the model's values

void expect_within(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, kTolerance * expected) << what;
}

TEST(DaylightAvailability, ClearSkyIrradianceFollowsIneichenPerezWithinTwoPercent) {
  // T_L = 3, sea level, mean extraterrestrial irradiance (1367 W/m²): G, B_n, D in W/m².
  struct Case {
    double altitude, global, beam, diffuse;
  };
  for (const Case c : {Case{10, 107.721, 413.615, 35.8977}, Case{30, 470.655, 789.54, 75.8851},
                       Case{60, 898.737, 918.466, 103.323}}) {
    const SolarIrradiance r = clear_sky_irradiance(horizontal_to_world(180, c.altitude), 0, 0, 3);
    expect_within(r.global_horizontal, c.global, "G");
    expect_within(r.direct_normal, c.beam, "B_n");
    expect_within(r.diffuse_horizontal, c.diffuse, "D");
    // The split adds up: G = B_n·sin h + D.
    EXPECT_NEAR(r.direct_normal * std::sin(c.altitude * kPi / 180) + r.diffuse_horizontal,
                r.global_horizontal, 1e-9 * r.global_horizontal);
  }
  // Kasten & Young 1989: AM(30° zenith) = 1/(cos 30° + 0.50572·66.07995^−1.6364) = 1.15400.
  EXPECT_NEAR(kasten_young_air_mass(kPi / 6), 1.15400, 1e-5);
}

TEST(DaylightAvailability, SkyTypesOneSevenTwelveAndOvercastMatchTheModelWithinTwoPercent) {
  // The dome's diffuse horizontal illuminance and the sun's normal illuminance (lx) by hand:
  // overcast types 8 oktas (no sun), type 7 4 oktas, type 12 cloudless; T_L 3, sea level.
  struct Case {
    int type;
    double altitude, sky, sun;
  };
  for (const Case c : {Case{0, 10, 3179.82, 0}, Case{0, 30, 13887.7, 0}, Case{0, 60, 27305.4, 0},
                       Case{1, 10, 3179.82, 0}, Case{1, 30, 13887.7, 0}, Case{1, 60, 27305.4, 0},
                       Case{7, 10, 7014.16, 18773.9}, Case{7, 30, 26911.1, 42141.4},
                       Case{7, 60, 47141.9, 48649.1}, Case{12, 10, 5857.41, 29129.3},
                       Case{12, 30, 11378.9, 78996.3}, Case{12, 60, 13761.9, 95032.1}}) {
    SCOPED_TRACE(testing::Message() << "type " << c.type << " at " << c.altitude << "°");
    const DaylightAvailability d =
        cie_sky_daylight(c.type, horizontal_to_world(180, c.altitude), 0, 0, 3);
    expect_within(d.sky_horizontal_illuminance, c.sky, "sky");
    if (c.sun == 0) {
      EXPECT_EQ(d.sun_normal_illuminance, 0);
    } else {
      expect_within(d.sun_normal_illuminance, c.sun, "sun");
    }
  }
  // A high summer site: 21 June (day 172), 500 m, T_L 4, type 12 at 45°.
  const DaylightAvailability summer =
      cie_sky_daylight(12, horizontal_to_world(180, 45), 172, 500, 4);
  expect_within(summer.sky_horizontal_illuminance, 16476.5, "sky");
  expect_within(summer.sun_normal_illuminance, 77225.3, "sun");
}

TEST(DaylightAvailability, NothingAtOrBelowTheHorizon) {
  for (const double altitude : {0.0, -0.5, -6.0, -30.0}) {
    for (const int type : {0, 1, 7, 12, 15}) {
      const DaylightAvailability d =
          cie_sky_daylight(type, horizontal_to_world(90, altitude), 100, 0, 3);
      EXPECT_EQ(d.sky_horizontal_illuminance, 0);
      EXPECT_EQ(d.sun_normal_illuminance, 0);
    }
  }
}

TEST(DaylightAvailability, BrighterWithAltitudeAndElevationDimmerWithTurbidity) {
  const auto sun = [](double altitude) { return horizontal_to_world(200, altitude); };
  double last = 0;
  for (double h = 2; h <= 88; h += 2) {
    const double sky = cie_sky_daylight(12, sun(h), 80, 0, 3).sky_horizontal_illuminance;
    EXPECT_GT(sky, last) << h;
    last = sky;
  }
  EXPECT_GT(clear_sky_irradiance(sun(40), 80, 2000, 3).direct_normal,
            clear_sky_irradiance(sun(40), 80, 0, 3).direct_normal);
  EXPECT_LT(clear_sky_irradiance(sun(40), 80, 0, 6).direct_normal,
            clear_sky_irradiance(sun(40), 80, 0, 3).direct_normal);
}

EnvironmentSpec parse(const nlohmann::json& j, const Site* site) {
  const JsonNode root(j, "test.json", "/");
  return parse_environment(root, ".", true, site);
}

TEST(DaylightAvailability, ASkyWithoutBrightnessTakesTheModelsAndTheSitesPlace) {
  Site site;
  site.latitude_deg = 48.14;
  site.longitude_deg = 11.58;
  site.utc_offset_hours = 1;
  site.elevation_m = 520;
  const EnvironmentSpec spec = parse(
      {{"type", "cie_sky"}, {"sky_type", 12}, {"sun", {{"datetime", "2026-06-21T13:00"}}}}, &site);
  EXPECT_EQ(spec.scaling, SkyScaling::kSunAltitude);
  EXPECT_TRUE(spec.sun.place_from_site);
  EXPECT_DOUBLE_EQ(spec.sun.latitude_deg, 48.14);
  const Environment env = make_environment(spec);
  const Vec3 s = sun_direction(spec.sun);
  const DaylightAvailability d = cie_sky_daylight(12, s, 172, 520, kDefaultLinkeTurbidity);
  EXPECT_NEAR(env.sky.sky_horizontal_illuminance, d.sky_horizontal_illuminance,
              1e-6 * d.sky_horizontal_illuminance);
  ASSERT_TRUE(env.sun().has_value());
  EXPECT_NEAR(env.sun()->normal_illuminance, d.sun_normal_illuminance, 1e-6 * 1e5);
  // The sun at midnight: a black sky.
  const Environment night = make_environment(parse(
      {{"type", "cie_sky"}, {"sky_type", 12}, {"sun", {{"datetime", "2026-06-21T23:30"}}}}, &site));
  EXPECT_EQ(night.sky.sky_horizontal_illuminance, 0);
  EXPECT_FALSE(night.sun().has_value());
  EXPECT_EQ(night.radiance({0, 1, 0}).g, 0);
}

TEST(DaylightAvailability, ASunByDatetimeAloneNeedsASite) {
  EXPECT_THROW(
      parse({{"type", "cie_sky"}, {"sky_type", 12}, {"sun", {{"datetime", "2026-06-21T13:00"}}}},
            nullptr),
      InputError);
  // A brightness together with the model's turbidity is refused.
  Site site;
  EXPECT_THROW(parse({{"type", "cie_sky"},
                      {"sky_type", "overcast"},
                      {"horizontal_illuminance", 10000},
                      {"linke_turbidity", 3},
                      {"sun", {{"datetime", "2026-06-21T13:00"}}}},
                     &site),
               InputError);
}

TEST(DaylightAvailability, NorthTurnsEverySunClockwise) {
  Site site;
  site.north_deg = 90;
  const EnvironmentSpec spec = parse({{"type", "cie_sky"},
                                      {"sky_type", 12},
                                      {"horizontal_illuminance", 10000},
                                      {"sun", {{"azimuth_deg", 180}, {"altitude_deg", 30}}}},
                                     &site);
  // True south (+z when north is −z) turns a quarter clockwise, seen from above: onto −x.
  const Vec3 s = make_environment(spec).sky.sun_direction;
  EXPECT_NEAR(s.x, -std::cos(kPi / 6), 1e-9);
  EXPECT_NEAR(s.z, 0, 1e-9);
  EXPECT_NEAR(s.y, 0.5, 1e-9);
}

}  // namespace
}  // namespace relight
