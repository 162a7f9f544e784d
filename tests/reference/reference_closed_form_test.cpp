// The reference path tracer against closed forms (CIE 171:2006 style):
//  - point source over a black plane: E = I·h / (h² + x²)^{3/2};
//  - closed sphere with a central isotropic source: E = E_direct / (1 − ρ) everywhere.
#include <cmath>

#include <gtest/gtest.h>

#include "light/luminaire_frame.h"
#include "reference/reference_tracer.h"
#include "scene/scene_loader.h"
#include "support/scene_json.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

using nlohmann::json;

std::vector<Rgb> trace_sensors(const json& document, int spp) {
  const Scene scene = scene_from_json(document, "closed-form.json");
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  const ReferenceScene ref = make_reference_scene(scene, mesh, traced, luminaires);
  ReferenceSettings settings;
  settings.spp = spp;
  settings.seed = 7;
  settings.progress = false;
  return reference_sensor_illuminance(scene, ref, settings);
}

TEST(ReferenceClosedForm, IsotropicPointOverBlackPlaneWithinOnePercent) {
  const double h = 2.0, intensity = 100.0;
  json points = json::array();
  for (int k = 0; k <= 6; ++k) points.push_back({0.5 * k, 0.0, 0.0});
  const json scene = {{"materials", {{"black", {{"albedo", {0, 0, 0}}}}}},
                      {"geometry",
                       {{{"type", "quad"},
                         {"corner", {-20, 0, -20}},
                         {"u", {0, 0, 40}},
                         {"v", {40, 0, 0}},
                         {"material", "black"}}}},
                      {"luminaires",
                       {{{"name", "point"},
                         {"position", {0, h, 0}},
                         {"distribution", {{"type", "isotropic"}, {"candela", intensity}}}}}},
                      {"sensors", {{{"name", "line"}, {"points", points}, {"normal", {0, 1, 0}}}}}};
  const std::vector<Rgb> e = trace_sensors(scene, 4);
  ASSERT_EQ(e.size(), 7u);
  for (int k = 0; k <= 6; ++k) {
    const double x = 0.5 * k;
    const double expected = intensity * h / std::pow(h * h + x * x, 1.5);
    EXPECT_NEAR(luminance(e[k]), expected, 0.01 * expected) << "x = " << x;
  }
}

class ClosedSphere : public ::testing::TestWithParam<double> {};

TEST_P(ClosedSphere, EverySensorWithinTwoPercentOfDirectOverOneMinusRho) {
  const double rho = GetParam(), radius = 2.0, intensity = 100.0;
  // Sensors just inside the tessellated sphere (level 5: sagitta < 2e-4 R), facing the
  // centre, in assorted directions.
  const double r = radius * 0.999;
  json points = json::array();
  const Vec3 dirs[] = {{1, 0, 0},  {0, 1, 0}, {0, 0, 1},    {-1, 0, 0},   {0, -1, 0},
                       {0, 0, -1}, {1, 1, 1}, {-1, 2, 0.5}, {0.3, -1, 2}, {2, 0.1, -1}};
  json sets = json::array();
  int k = 0;
  for (Vec3 d : dirs) {
    const Vec3 u = normalize(d);
    sets.push_back({{"name", std::to_string(k++)},
                    {"points", {{u.x * r, u.y * r, u.z * r}}},
                    {"normal", {-u.x, -u.y, -u.z}}});
  }
  const json scene = testing::closed_sphere(rho, radius, intensity, sets);
  const std::vector<Rgb> e = trace_sensors(scene, 16384);
  const double expected = intensity / (r * r) / (1 - rho);
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_NEAR(luminance(e[i]), expected, 0.02 * expected) << "sensor " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Albedo, ClosedSphere, ::testing::Values(0.5, 0.8));

TEST(ReferenceDeterminism, SameSeedSameNumbers) {
  const json scene = {{"materials", {{"grey", {{"albedo", {0.5, 0.5, 0.5}}}}}},
                      {"geometry",
                       {{{"type", "box"},
                         {"min", {0, 0, 0}},
                         {"max", {2, 2, 2}},
                         {"normals", "inward"},
                         {"material", "grey"}}}},
                      {"luminaires",
                       {{{"name", "l"},
                         {"position", {1, 1.5, 1}},
                         {"distribution", {{"type", "isotropic"}, {"candela", 50}}}}}},
                      {"sensors", {{{"name", "p"}, {"points", {{1, 0.5, 1}, {0.5, 1, 0.5}}}}}}};
  const std::vector<Rgb> a = trace_sensors(scene, 64), b = trace_sensors(scene, 64);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].g, b[i].g);
}

}  // namespace
}  // namespace relight
