// Glazing (math/glazing.h) through the run time, against closed forms and the reference tracer:
//  * the sun behind one and two panes over the sun through an open skylight, at incidence 0–80°:
//    the panes' transmittance at the sun's incidence within 1%;
//  * glazed openings under the CIE overcast sky in the manner of CIE 171:2006's glazed roof and
//    façade openings (a black room, daylight factors on the floor), against this test's own
//    numerical integration of L·T(θ)·cos over the opening, within 5% per point;
//  * diffusing glass in a grey room under a clear sky with sun, against `relight reference`,
//    within 3% mean.
// Every test prints its figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "light/sun_position.h"
#include "math/glazing.h"
#include "sources/transfer_file.h"
#include "support/daylight_harness.h"
#include "support/daylight_room.h"
#include "support/precomputed_file.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using nlohmann::json;

json glazing_json(double t, int panes, bool diffusing) {
  return {{"visible_transmittance", t}, {"panes", panes}, {"diffusing", diffusing}};
}

constexpr double kSunNormal = 100000;

// A black room under the skylight; per incidence angle θ = 0°, 10°, … 80° a sensor 0.5 m below
// the skylight's centre along the sun's ray, facing the sun (due south at altitude 90° − θ).
TEST(GlazingAccuracy, SunThroughOneAndTwoPanesFollowsTheirTransmittanceWithinOnePercent) {
  testing::WindowRoom room;
  room.skylight = testing::kSkylight;
  json scene = testing::window_room_json(room);
  const Vec3 centre{2, 3, 2.75};
  json sensors = json::array();
  std::vector<double> incidence;
  for (int deg = 0; deg <= 80; deg += 10) {
    incidence.push_back(deg);
    const Vec3 s = horizontal_to_world(180, 90.0 - deg);
    const Vec3 p = centre - s * 0.5;
    sensors.push_back({{"name", "facing the sun at " + std::to_string(deg)},
                       {"points", {{p.x, p.y, p.z}}},
                       {"normal", {s.x, s.y, s.z}}});
  }
  scene["sensors"] = sensors;
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 16}, {"sensor_gather_rays", 16}};
  const testing::Daylight day(scene);
  const auto sky_with_sun = [](double altitude) {
    return json{{"type", "cie_sky"},
                {"sky_type", 12},
                {"horizontal_illuminance", 0},
                {"sun", {{"azimuth_deg", 180}, {"altitude_deg", altitude}}},
                {"sun_illuminance", kSunNormal}};
  };
  const Glazing single = make_glazing(0.88, 1, false);
  const Glazing dbl = make_glazing(0.78, 2, false);
  for (std::size_t k = 0; k < incidence.size(); ++k) {
    const json env = sky_with_sun(90 - incidence[k]);
    const double open =
        luminance(day.sensors(testing::portal_state("skylight", {{"environment", env}}))[k]);
    const double one = luminance(day.sensors(testing::portal_state(
        "skylight", {{"environment", env}, {"glazing", glazing_json(0.88, 1, false)}}))[k]);
    const double two = luminance(day.sensors(testing::portal_state(
        "skylight", {{"environment", env}, {"glazing", glazing_json(0.78, 2, false)}}))[k]);
    const double c = std::cos(incidence[k] * kPi / 180);
    std::printf(
        "incidence %2.0f°: open %.0f lx, one pane %.4f (closed form %.4f), two %.4f (%.4f)\n",
        incidence[k], open, one / open, glazing_transmittance(single, c), two / open,
        glazing_transmittance(dbl, c));
    EXPECT_NEAR(open, kSunNormal, 0.01 * kSunNormal);
    EXPECT_NEAR(one / open, glazing_transmittance(single, c),
                0.01 * glazing_transmittance(single, c));
    EXPECT_NEAR(two / open, glazing_transmittance(dbl, c), 0.01 * glazing_transmittance(dbl, c));
  }
}

// E at p facing up from a CIE overcast sky (zenith luminance lz) through the rectangle
// corner + [0,1]·u + [0,1]·v behind glazing g: ∫ L(ω)·T(θ)·cos θ_p·cos θ_A / r² dA, midpoint rule.
double overcast_through_opening(Vec3 p, Vec3 corner, Vec3 u, Vec3 v, const Glazing& g, double lz) {
  constexpr int kSteps = 400;
  const Vec3 normal = normalize(cross(u, v));
  const double da = length(cross(u, v)) / (kSteps * kSteps);
  double e = 0;
  for (int i = 0; i < kSteps; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      const Vec3 a = corner + u * ((i + 0.5) / kSteps) + v * ((j + 0.5) / kSteps);
      const Vec3 d = a - p;
      const double r2 = dot(d, d);
      const Vec3 w = d / std::sqrt(r2);
      if (w.y <= 0) continue;
      const double cos_glass = std::abs(dot(w, normal));
      const double l = lz * (1 + 2 * w.y) / 3;
      e += l * glazing_transmittance(g, cos_glass) * w.y * cos_glass / r2 * da;
    }
  }
  return e;
}

TEST(GlazingAccuracy, GlazedRoofAndFacadeOpeningsUnderTheOvercastSkyWithinFivePercentPerPoint) {
  constexpr double kHorizontal = 10000;           // lx of the unobstructed sky
  const double lz = kHorizontal / (7 * kPi / 9);  // its zenith luminance
  const json overcast = {
      {"type", "cie_sky"}, {"sky_type", "overcast"}, {"horizontal_illuminance", kHorizontal}};
  const Glazing g = make_glazing(0.75, 2, false);
  testing::WindowRoom room;
  room.skylight = testing::kSkylight;
  room.south_window = testing::kWindow;
  json scene = testing::window_room_json(room);
  for (json& p : scene["portals"]) p["environment"] = overcast;
  for (const char* glass : {"skylight glass", "window glass"}) {
    scene["materials"][glass]["glazing"] = glazing_json(0.75, 2, false);
  }
  const std::vector<Vec3> points =
      testing::grid_points({0.5, 0.0, 0.5}, {3, 0, 0}, {0, 0, 4}, 3, 4);
  scene["sensors"] = {testing::sensor_points("floor", points)};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 16}, {"sensor_gather_rays", 16}};
  const testing::Daylight day(scene);
  const auto only = [&](const char* open) {
    json state = {{"portals", json::object()}};
    for (const char* p : {"skylight", "south window"}) {
      if (std::string(p) != open) state["portals"][p] = {{"tint", {0, 0, 0}}};
    }
    return day.sensors(state);
  };
  const std::vector<Rgb> roof = only("skylight");
  const std::vector<Rgb> facade = only("south window");
  double worst_roof = 0, worst_facade = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    const double roof_expected =
        overcast_through_opening(p, {testing::kSkylight.u0, 3, testing::kSkylight.v0},
                                 {testing::kSkylight.u1 - testing::kSkylight.u0, 0, 0},
                                 {0, 0, testing::kSkylight.v1 - testing::kSkylight.v0}, g, lz);
    const double facade_expected =
        overcast_through_opening(p, {testing::kWindow.u0, testing::kWindow.v0, 5},
                                 {testing::kWindow.u1 - testing::kWindow.u0, 0, 0},
                                 {0, testing::kWindow.v1 - testing::kWindow.v0, 0}, g, lz);
    const double r = luminance(roof[i]), f = luminance(facade[i]);
    std::printf("(%.1f, %.1f): roof DF %.3f%% (integral %.3f%%), facade DF %.3f%% (%.3f%%)\n", p.x,
                p.z, 100 * r / kHorizontal, 100 * roof_expected / kHorizontal,
                100 * f / kHorizontal, 100 * facade_expected / kHorizontal);
    worst_roof = std::max(worst_roof, std::abs(r - roof_expected) / roof_expected);
    worst_facade = std::max(worst_facade, std::abs(f - facade_expected) / facade_expected);
    EXPECT_NEAR(r, roof_expected, 0.05 * roof_expected);
    EXPECT_NEAR(f, facade_expected, 0.05 * facade_expected);
  }
  std::printf("worst: roof %.4f, facade %.4f\n", worst_roof, worst_facade);
}

TEST(GlazingAccuracy, DiffusingGlassWithinThreePercentOfTheReferenceOnAverage) {
  json scene = testing::south_window_room(0.8);
  scene["materials"]["window glass"]["glazing"] = glazing_json(0.7, 1, true);
  scene["portals"][0]["environment"] = {{"type", "cie_sky"},
                                        {"sky_type", 12},
                                        {"horizontal_illuminance", 12000},
                                        {"sun", {{"azimuth_deg", 170}, {"altitude_deg", 35}}},
                                        {"sun_illuminance", 80000}};
  const testing::Daylight day(scene);
  const std::vector<Rgb> fast = day.sensors();
  const std::vector<Rgb> truth = testing::reference(scene, 4096);
  const testing::Comparison c = testing::compare(fast, truth, "diffusing glass");
  EXPECT_LT(c.mean, 0.03);
}

TEST(GlazingAccuracy, ATransferFileKeepsItsPortalsGlazing) {
  json scene = testing::south_window_room(0.8);
  scene["materials"]["window glass"]["glazing"] = glazing_json(0.7, 2, true);
  scene["precompute"] = {{"max_edge", 1.0}, {"gather_rays", 8}, {"sensor_gather_rays", 8}};
  const testing::TempDir dir;
  const TransferFile file = open_transfer_file(testing::write_precomputed(dir, "glazed", scene));
  ASSERT_TRUE(file.scene.portals.at(0).glazing.has_value());
  EXPECT_EQ(*file.scene.portals[0].glazing, make_glazing(0.7, 2, true));
}

}  // namespace
}  // namespace relight
