// The sensors' importance (engine/sensor_importance.h) against the forward bounce it stands
// for, and against a closed form: in a room of coloured walls lit on a patch, every sensor's
// bounced light through its importance equals solve_bounces_rgb's at the sensor rows within
// 1e-5 of the brightest (both solved to 1e-7); inside a closed sphere of albedo ρ under
// uniform light E_d a sensor receives E_d·ρ/(1 − ρ) (the row of G sums to 1) within 0.5 %.
#include "engine/sensor_importance.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/gather_operator.h"
#include "scene/primitives.h"

namespace relight {
namespace {

struct Rig {
  Receivers receivers;
  GatherOperator gather;
};

Rig make_rig(const Scene& scene, double max_edge) {
  PreparationSettings settings;
  settings.max_edge = max_edge;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, settings);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  Receivers receivers = make_receivers(scene, mesh);
  GatherOperator gather = build_gather_operator(receivers, mesh, traced, 64, 256, 7, false);
  return {std::move(receivers), std::move(gather)};
}

void add_sensor(Scene& scene, Vec3 at, Vec3 normal) {
  std::string name = "s";
  name += std::to_string(scene.sensors.size());
  scene.sensors.push_back({name, {at}, normalize(normal)});
}

// A 4 × 3 × 5 m box room: red floor, white walls, a blue block on the floor; five sensors.
Scene coloured_room() {
  Scene scene;
  scene.materials = {
      {"walls", {0.8, 0.8, 0.8}}, {"floor", {0.6, 0.2, 0.1}}, {"block", {0.1, 0.2, 0.7}}};
  scene.geometry = make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0);
  scene.geometry.append(make_quad({0, 0.001, 0}, {0, 0, 5}, {4, 0, 0}, 1));
  scene.geometry.append(make_box({2.5, 0.0, 3}, {3.5, 0.8, 4}, Facing::kOutward, 2));
  add_sensor(scene, {1, 0.8, 1}, {0, 1, 0});
  add_sensor(scene, {2, 0.8, 2.5}, {0, 1, 0});
  add_sensor(scene, {3, 1.5, 1}, {0, 0, 1});
  add_sensor(scene, {0.5, 2.5, 4}, {1, -1, 0});
  add_sensor(scene, {2, 2.9, 2.5}, {0, -1, 0});
  return scene;
}

TEST(SensorImportance, EqualsTheForwardBounceAtEverySensorWithin1e5) {
  const Scene scene = coloured_room();
  const Rig rig = make_rig(scene, 0.5);
  BounceSettings tight;
  tight.tolerance = 1e-7;
  const SensorImportance importance = sensor_importance(rig.gather, rig.receivers, tight);
  ASSERT_EQ(importance.sensors, scene.sensors.size());
  const std::size_t n = rig.receivers.size();
  // A sun patch: light on the floor near the far wall and on part of a wall, RGB.
  std::vector<float> direct(3 * n, 0.0f);
  std::size_t lit = 0;
  for (std::size_t v = 0; v < rig.receivers.vertex_count; ++v) {
    const Vec3 p = rig.receivers.positions[v];
    if ((p.y < 0.01 && p.z > 2 && p.x < 2.5) || (p.x > 3.99 && p.y > 1)) {
      direct[3 * v] = 1000.0f;
      direct[3 * v + 1] = 900.0f;
      direct[3 * v + 2] = 700.0f;
      ++lit;
    }
  }
  ASSERT_GT(lit, 20u);
  std::vector<float> forward(3 * n, 0.0f);
  solve_bounces_rgb(rig.gather, rig.receivers, direct, forward, false, tight);
  std::vector<float> adjoint(3 * scene.sensors.size());
  sensor_indirect(importance, direct, adjoint);
  float brightest = 0;
  for (const float e : adjoint) brightest = std::max(brightest, e);
  ASSERT_GT(brightest, 10.0f);
  for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float expected = forward[3 * (rig.receivers.vertex_count + s) + c];
      EXPECT_NEAR(adjoint[3 * s + c], expected, 1e-5 * brightest) << "sensor " << s << " c " << c;
    }
  }
}

TEST(SensorImportance, AClosedSphereGivesRhoOverOneMinusRhoOfUniformLight) {
  Scene scene;
  const Rgb albedo{0.7, 0.5, 0.3};
  scene.materials = {{"wall", albedo}};
  scene.geometry = make_sphere({0, 0, 0}, 2, Facing::kInward, 3, 0);
  add_sensor(scene, {0, 0, 0}, {0, 1, 0});
  add_sensor(scene, {1.2, -0.5, 0.3}, {-1, 0.2, 0});
  const Rig rig = make_rig(scene, 0);
  const SensorImportance importance = sensor_importance(rig.gather, rig.receivers, {});
  const std::vector<float> direct(3 * rig.receivers.size(), 100.0f);
  std::vector<float> out(3 * scene.sensors.size());
  sensor_indirect(importance, direct, out);
  for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double rho = c == 0 ? albedo.r : (c == 1 ? albedo.g : albedo.b);
      EXPECT_NEAR(out[3 * s + c], 100 * rho / (1 - rho), 0.005 * 100 * rho / (1 - rho))
          << "sensor " << s << " channel " << c;
    }
  }
}

TEST(SensorImportance, RefusesLightOfTheWrongSize) {
  const Rig rig = make_rig(coloured_room(), 1.0);
  const SensorImportance importance = sensor_importance(rig.gather, rig.receivers, {});
  std::vector<float> out(3 * importance.sensors);
  EXPECT_THROW(sensor_indirect(importance, std::vector<float>(5), out), std::invalid_argument);
}

}  // namespace
}  // namespace relight
