// Parsing of ENV objects: every type with its defaults, and errors that name the JSON path.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "common/input_error.h"
#include "scene/environment_spec.h"
#include "scene/json_node.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using nlohmann::json;

EnvironmentSpec parse(const std::string& text, const std::filesystem::path& base = ".") {
  const json doc = json::parse(text);
  const JsonNode root(doc, "scene.json", "/");
  return parse_environment(root.at("env"), base);
}

// The InputError message of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text, const std::filesystem::path& base = ".") {
  try {
    parse(text, base);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(EnvironmentSpec, Uniform) {
  const EnvironmentSpec s = parse(R"({"env": {"type": "uniform", "luminance": 3000}})");
  EXPECT_EQ(s.type, EnvironmentType::kUniform);
  EXPECT_EQ(s.luminance, 3000);
  EXPECT_EQ(s.color.r, 1);
  EXPECT_EQ(s.where, "scene.json:/env");
  const EnvironmentSpec t =
      parse(R"({"env": {"type": "uniform", "luminance": 10, "color": [1, 0.5, 0.25]}})");
  EXPECT_EQ(t.color.g, 0.5);
}

TEST(EnvironmentSpec, Map) {
  testing::TempDir dir;
  dir.write("sky.exr", "x");
  const EnvironmentSpec s = parse(
      R"({"env": {"type": "map", "file": "sky.exr", "rotate_deg": -45, "scale": 2}})", dir.path());
  EXPECT_EQ(s.type, EnvironmentType::kMap);
  EXPECT_EQ(s.file, dir.path() / "sky.exr");
  EXPECT_EQ(s.rotate_deg, -45);
  EXPECT_EQ(s.scale, 2);
  const EnvironmentSpec d = parse(R"({"env": {"type": "map", "file": "sky.exr"}})", dir.path());
  EXPECT_EQ(d.rotate_deg, 0);
  EXPECT_EQ(d.scale, 1);
}

TEST(EnvironmentSpec, CieSkyWithPlaceAndTime) {
  const EnvironmentSpec s = parse(R"({"env": {
      "type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
      "sun": {"latitude": 48.85, "longitude": 2.35, "utc_offset": 2,
              "datetime": "2024-06-21T14:30"},
      "sun_illuminance": 85000}})");
  EXPECT_EQ(s.type, EnvironmentType::kCieSky);
  EXPECT_EQ(s.sky_type, 12);
  EXPECT_EQ(s.scaling, SkyScaling::kHorizontalIlluminance);
  EXPECT_EQ(s.scaling_value, 15000);
  EXPECT_EQ(s.ground_albedo, 0.2);
  EXPECT_EQ(s.sun.placement, SunPlacement::kPlaceAndTime);
  EXPECT_EQ(s.sun.latitude_deg, 48.85);
  EXPECT_EQ(s.sun.utc_offset_hours, 2);
  EXPECT_EQ(s.sun.local_time.year, 2024);
  EXPECT_EQ(s.sun.local_time.hour, 14);
  EXPECT_EQ(s.sun.local_time.minute, 30);
  EXPECT_EQ(s.sun_illuminance, 85000);
}

TEST(EnvironmentSpec, CieSkyDefaults) {
  const EnvironmentSpec s =
      parse(R"({"env": {"type": "cie_sky", "sky_type": "overcast", "zenith_luminance": 5000}})");
  EXPECT_EQ(s.sky_type, kTraditionalOvercastSky);
  EXPECT_EQ(s.scaling, SkyScaling::kZenithLuminance);
  EXPECT_EQ(s.ground_albedo, 0.2);
  EXPECT_EQ(s.sun.placement, SunPlacement::kNone);
  EXPECT_EQ(s.sun_illuminance, 0);
  const EnvironmentSpec a = parse(R"({"env": {"type": "cie_sky", "sky_type": 7,
      "zenith_luminance": 5000, "ground_albedo": 0.1,
      "sun": {"azimuth_deg": 225, "altitude_deg": 30}}})");
  EXPECT_EQ(a.sun.placement, SunPlacement::kAngles);
  EXPECT_EQ(a.sun.azimuth_deg, 225);
  EXPECT_EQ(a.sun.altitude_deg, 30);
  EXPECT_EQ(a.sun.utc_offset_hours, 0);
}

TEST(EnvironmentSpec, PerezSkyFromAWeatherRecord) {
  const EnvironmentSpec s = parse(R"({"env": {"type": "perez", "direct_normal_irradiance": 640,
      "diffuse_horizontal_irradiance": 120.5, "dew_point_c": -3.5,
      "sun": {"latitude": 48.1, "longitude": 11.6, "utc_offset": 1,
              "datetime": "2025-03-01T11:30"}}})");
  EXPECT_EQ(s.type, EnvironmentType::kPerezSky);
  EXPECT_EQ(s.direct_normal_irradiance, 640);
  EXPECT_EQ(s.diffuse_horizontal_irradiance, 120.5);
  ASSERT_TRUE(s.dew_point_c.has_value());
  EXPECT_EQ(*s.dew_point_c, -3.5);
  EXPECT_EQ(s.ground_albedo, 0.2);
  EXPECT_EQ(s.sun.placement, SunPlacement::kPlaceAndTime);
  EXPECT_EQ(day_of_year(s.sun.local_time), 60);
  EXPECT_EQ(day_of_year({2024, 3, 1, 0, 0, 0}), 61);  // a leap year
  EXPECT_EQ(day_of_year({2023, 12, 31, 0, 0, 0}), 365);
  const EnvironmentSpec no_dew = parse(R"({"env": {"type": "perez", "direct_normal_irradiance": 0,
      "diffuse_horizontal_irradiance": 80, "ground_albedo": 0.35,
      "sun": {"azimuth_deg": 120, "altitude_deg": 20}}})");
  EXPECT_FALSE(no_dew.dew_point_c.has_value());
  EXPECT_EQ(no_dew.ground_albedo, 0.35);
  EXPECT_NE(s, no_dew);
}

TEST(EnvironmentSpec, PerezSkyJsonReadsBackAsTheSameSky) {
  const std::string place = R"({"env": {"type": "perez", "direct_normal_irradiance": 640,
      "diffuse_horizontal_irradiance": 120.5, "dew_point_c": -3.5, "ground_albedo": 0.31,
      "sun": {"latitude": 41.98, "longitude": -87.92, "utc_offset": -6,
              "datetime": "1988-07-21T13:30:15.5"}}})";
  const std::string angles = R"({"env": {"type": "perez", "direct_normal_irradiance": 0,
      "diffuse_horizontal_irradiance": 80, "sun": {"azimuth_deg": 120, "altitude_deg": 20}}})";
  for (const std::string& text : {place, angles}) {
    EnvironmentSpec sky = parse(text);
    const json back = {{"env", perez_sky_json(sky)}};
    EnvironmentSpec again = parse(back.dump());
    sky.where = again.where = "";
    EXPECT_EQ(again, sky) << back.dump();
  }
  const Site site{48.14, 11.58, 1, 520, 30};
  const json doc = json::parse(R"({"env": {"type": "perez", "direct_normal_irradiance": 500,
      "diffuse_horizontal_irradiance": 90, "sun": {"datetime": "2026-06-21T12:00"}}})");
  const EnvironmentSpec at_site =
      parse_environment(JsonNode(doc, "s.json", "/").at("env"), ".", true, &site);
  const json back = {{"env", perez_sky_json(at_site)}};
  EXPECT_FALSE(back["env"]["sun"].contains("latitude")) << back.dump();
  EnvironmentSpec again =
      parse_environment(JsonNode(back, "s.json", "/").at("env"), ".", true, &site);
  again.where = at_site.where;
  EXPECT_EQ(again, at_site);
  EnvironmentSpec cie = at_site;
  cie.type = EnvironmentType::kCieSky;
  EXPECT_THROW(perez_sky_json(cie), std::logic_error);
}

TEST(EnvironmentSpec, ErrorsNameTheJsonPath) {
  struct Case {
    const char* text;
    const char* expected;  // a substring of the message
  };
  testing::TempDir dir;
  dir.write("picture.png", "x");
  const Case cases[] = {
      {R"({"env": {"type": "uniform", "luminance": 1, "bogus": 2}})",
       "scene.json:/env/bogus: unknown key \"bogus\""},
      {R"({"env": {"type": "sunny"}})", "scene.json:/env/type: unknown environment type"},
      {R"({"env": {"type": "perez", "direct_normal_irradiance": 100,
           "diffuse_horizontal_irradiance": 50}})",
       "scene.json:/env: missing required key \"sun\""},
      {R"({"env": {"type": "perez", "direct_normal_irradiance": 9999,
           "diffuse_horizontal_irradiance": 50, "sun": {"azimuth_deg": 0, "altitude_deg": 9}}})",
       "scene.json:/env/direct_normal_irradiance: must lie in 0..1500"},
      {R"({"env": {"type": "perez", "direct_normal_irradiance": 100,
           "sun": {"azimuth_deg": 0, "altitude_deg": 9}}})",
       "scene.json:/env: missing required key \"diffuse_horizontal_irradiance\""},
      {R"({"env": {"type": "perez", "direct_normal_irradiance": 1, "dew_point_c": "warm",
           "diffuse_horizontal_irradiance": 50, "sun": {"azimuth_deg": 0, "altitude_deg": 9}}})",
       "scene.json:/env/dew_point_c: expected a number"},
      {R"({"env": {"type": "perez", "direct_normal_irradiance": 1, "sky_type": 3,
           "diffuse_horizontal_irradiance": 50, "sun": {"azimuth_deg": 0, "altitude_deg": 9}}})",
       "scene.json:/env/sky_type: unknown key"},
      {R"({"env": {"type": "uniform"}})", "scene.json:/env: missing required key \"luminance\""},
      {R"({"env": {"type": "uniform", "luminance": -1}})", "scene.json:/env/luminance: must be"},
      {R"({"env": {"type": "uniform", "luminance": 1, "color": [0, 0, 0]}})",
       "scene.json:/env/color: colour must have a positive luminance"},
      {R"({"env": {"type": "map", "file": "none.exr"}})", "scene.json:/env/file: file not found"},
      {R"({"env": {"type": "map", "file": "picture.png"}})",
       "scene.json:/env/file: expected an OpenEXR (.exr) or Radiance (.hdr) file"},
      {R"({"env": {"type": "map", "file": "none.hdr", "scale": -1}})",
       "scene.json:/env/file: file not found"},
      {R"({"env": {"type": "cie_sky", "sky_type": 16, "zenith_luminance": 1}})",
       "scene.json:/env/sky_type: must be an integer in 1..15"},
      {R"({"env": {"type": "cie_sky", "sky_type": "clear", "zenith_luminance": 1}})",
       "scene.json:/env/sky_type: expected an integer 1..15 or \"overcast\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 2.5, "zenith_luminance": 1}})",
       "scene.json:/env/sky_type: expected an integer 1..15 or \"overcast\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 1}})",
       "scene.json:/env: a sky without \"horizontal_illuminance\" or \"zenith_luminance\" takes "
       "its brightness from the sun's altitude: give \"sun\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "horizontal_illuminance": 1}})",
       "scene.json:/env: give at most one of"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "sun": {"datetime": "2026-06-21T12:00"}}})",
       "scene.json:/env/sun: a sun given by \"datetime\" alone stands at the project's site"},
      {R"({"env": {"type": "cie_sky", "sky_type": 12, "linke_turbidity": 12,
                   "sun": {"azimuth_deg": 180, "altitude_deg": 30}}})",
       "scene.json:/env/linke_turbidity: must lie in 1..10"},
      {R"({"env": {"type": "cie_sky", "sky_type": 12, "zenith_luminance": 1}})",
       "scene.json:/env/sky_type: CIE sky type 12 depends on the sun's position"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun_illuminance": 1000}})",
       "scene.json:/env/sun_illuminance: a sun_illuminance needs a \"sun\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"azimuth_deg": 10, "altitude_deg": 20}, "sun_illuminance": 2e5}})",
       "scene.json:/env/sun_illuminance: must lie in 0..140000"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "ground_albedo": 1.5}})",
       "scene.json:/env/ground_albedo: must lie in 0..1, got 1.5"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"azimuth_deg": 10, "latitude": 20}}})",
       "scene.json:/env/sun: give either"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"azimuth_deg": 10}}})",
       "scene.json:/env/sun: missing required key \"altitude_deg\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"azimuth_deg": 10, "altitude_deg": 95}}})",
       "scene.json:/env/sun/altitude_deg: must lie in -90..90, got 95"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"latitude": 95, "longitude": 0, "datetime": "2024-06-21T12:00"}}})",
       "scene.json:/env/sun/latitude: must lie in -90..90"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"latitude": 45, "longitude": 0, "datetime": "2023-02-29T12:00"}}})",
       "scene.json:/env/sun/datetime: expected a local date and time"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"latitude": 45, "longitude": 0, "utc_offset": 15,
                           "datetime": "2024-06-21T12:00"}}})",
       "scene.json:/env/sun/utc_offset: must lie in -14..14"},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"latitude": 45, "longitude": 0}}})",
       "scene.json:/env/sun: missing required key \"datetime\""},
      {R"({"env": {"type": "cie_sky", "sky_type": 1, "zenith_luminance": 1,
                   "sun": {"latitude": 45, "longitude": 0, "datetime": "2024-06-21T12:00",
                           "altitude": 3}}})",
       "scene.json:/env/sun/altitude: unknown key"},
      {R"({"env": [1, 2]})", "scene.json:/env: expected an environment object"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text, dir.path());
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "input: " << c.text << "\nmessage: " << message << "\nexpected: " << c.expected;
  }
}

TEST(EnvironmentSpec, CivilDateTime) {
  const auto a = parse_civil_datetime("2024-02-29T23:59");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->year, 2024);
  EXPECT_EQ(a->month, 2);
  EXPECT_EQ(a->day, 29);
  EXPECT_EQ(a->hour, 23);
  EXPECT_EQ(a->minute, 59);
  EXPECT_EQ(a->second, 0);
  const auto b = parse_civil_datetime("2000-12-31 06:07:08.25");
  ASSERT_TRUE(b.has_value());
  EXPECT_DOUBLE_EQ(b->second, 8.25);
  for (const char* bad :
       {"2023-02-29T12:00", "2100-02-29T12:00", "2024-06-21T24:00", "2024-06-21T12:60",
        "2024-06-21T12:00Z", "2024-06-21T12:00+02:00", "2024-6-21T12:00", "2024-06-21",
        "1900-06-21T12:00", "2024-06-21T12:00:60", "2024-06-21T12:00:5", "2024-06-21T12:00:05.",
        "2024-13-01T00:00", "2024-04-31T00:00", ""}) {
    EXPECT_FALSE(parse_civil_datetime(bad).has_value()) << bad;
  }
  EXPECT_TRUE(parse_civil_datetime("2000-02-29T00:00").has_value());  // 400-year leap rule
}

TEST(EnvironmentSpec, SkyTypesThatNeedTheSun) {
  for (int t = 0; t <= 15; ++t) {
    const bool expected = !(t == 0 || t == 1 || t == 3 || t == 5);
    EXPECT_EQ(sky_type_needs_sun(t), expected) << t;
  }
}

TEST(EnvironmentSpec, GlazingGlassCannotHaveIsRefusedWithTheMaximumAndThePath) {
  const auto message = [](const std::string& text) {
    const nlohmann::json root = nlohmann::json::parse(text);
    try {
      parse_glazing(JsonNode(root, "scene.json", "/").at("g"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(R"({"g": {"visible_transmittance": 0.95}})"),
            "scene.json:/g/visible_transmittance: uncoated glass of 1 pane transmits more than 0 "
            "and at most 0.918318 at normal incidence, got 0.95");
  EXPECT_EQ(message(R"({"g": {"visible_transmittance": 0, "panes": 2}})"),
            "scene.json:/g/visible_transmittance: uncoated glass of 2 panes transmits more than 0 "
            "and at most 0.848972 at normal incidence, got 0");
  EXPECT_NE(message(R"({"g": {"visible_transmittance": 0.7, "panes": 4}})").find("/g/panes"),
            std::string::npos);
  EXPECT_EQ(message(R"({"g": {"visible_transmittance": 0.7, "panes": 2, "diffusing": true}})"),
            "accepted");
}

}  // namespace
}  // namespace relight
