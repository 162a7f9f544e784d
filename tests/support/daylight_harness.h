// The daylight accuracy tests' harness (tests/render/daylight_accuracy_test.cpp,
// tests/render/sun_accuracy_test.cpp): one precompute of a scene in memory and a Relighter over
// it, the independent reference tracer's sensor readings of the same scene, sensor sets, and
// the comparison of two readings.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "light/environment.h"
#include "light/environment_map_io.h"
#include "light/luminaire_frame.h"
#include "reference/reference_tracer.h"
#include "runtime/lighting_state.h"
#include "runtime/relighter.h"
#include "scene/scene_loader.h"
#include "sources/portals/portal_lighting.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "trace/traced_scene.h"

namespace relight::testing {

using nlohmann::json;

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One precompute of a scene and a Relighter over it (map environments read from files).
// Neither copied nor moved: the Relighter points into the scene and the transfer.
class Daylight {
 public:
  explicit Daylight(const json& document) : scene_(scene_from_json(document, "daylight.json")) {
    const auto start = std::chrono::steady_clock::now();
    PrecomputeOptions options;
    options.progress = false;
    precomputed_ = precompute_transfer(scene_, options);
    relighter_ =
        std::make_unique<Relighter>(in_memory_view(precomputed_), scene_, RelighterSettings{});
    std::printf("precompute: %zu receivers (%zu sensors), %.2f s\n", precomputed_.receivers.size(),
                precomputed_.receivers.sensor_count, seconds_since(start));
  }
  Daylight(const Daylight&) = delete;
  Daylight& operator=(const Daylight&) = delete;

  const Scene& scene() const { return scene_; }
  const Relighter& relighter() const { return *relighter_; }

  LightingState state(const json& document) const {
    LightingState s = default_lighting_state(scene_);
    apply_lighting_state(s, scene_, document, "state.json", ".");
    return s;
  }

  // Sensor irradiance (RGB, scene order) under `document` applied to the scene's state.
  std::vector<Rgb> sensors(const json& document = json::object()) const {
    relighter_->set_state(state(document));
    std::vector<float> e(3 * relighter_->receivers());
    relighter_->relight(e);
    std::vector<Rgb> out;
    for (std::size_t s = 0; s < precomputed_.receivers.sensor_count; ++s) {
      const std::size_t r = 3 * (precomputed_.receivers.vertex_count + s);
      out.push_back({e[r], e[r + 1], e[r + 2]});
    }
    return out;
  }

 private:
  Scene scene_;
  Precomputed precomputed_;
  std::unique_ptr<Relighter> relighter_;
};

// The reference tracer's sensors of `document`, each portal showing its own environment.
inline std::vector<Rgb> reference(const json& document, int spp) {
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = scene_from_json(document, "reference.json");
  std::vector<Environment> environments;
  for (const Portal& portal : scene.portals) {
    environments.push_back(load_environment(portal.environment));
  }
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  ReferenceSettings settings;
  settings.spp = spp;
  settings.seed = 5;
  settings.progress = false;
  // The exterior objects where the scene puts them, in front of every portal.
  std::vector<std::vector<ExteriorObject>> exterior;
  for (const Portal& p : scene.portals) {
    if (!scene.exterior.empty()) {
      exterior.push_back(placed_exterior(scene, portal_state(p, scene.exterior.size()).exterior));
    }
  }
  const std::vector<Rgb> e = reference_sensor_illuminance(
      scene,
      make_reference_scene(scene, mesh, traced, luminaires, std::move(environments), {}, exterior),
      settings);
  std::printf("reference: %zu sensors × %d spp, %.2f s\n", e.size(), spp, seconds_since(start));
  return e;
}

inline json sensor_points(const std::string& name, const std::vector<Vec3>& points) {
  json p = json::array();
  for (Vec3 v : points) p.push_back({v.x, v.y, v.z});
  return {{"name", name}, {"points", p}, {"normal", {0, 1, 0}}};
}

inline json grid(const std::string& name, Vec3 corner, Vec3 u, Vec3 v, int nu, int nv,
                 Vec3 normal) {
  return {{"name", name},
          {"grid",
           {{"corner", {corner.x, corner.y, corner.z}},
            {"u", {u.x, u.y, u.z}},
            {"v", {v.x, v.y, v.z}},
            {"nu", nu},
            {"nv", nv}}},
          {"normal", {normal.x, normal.y, normal.z}}};
}

// Points of a grid sensor set, as docs/scene-format.md numbers them (j·nu + i).
inline std::vector<Vec3> grid_points(Vec3 corner, Vec3 u, Vec3 v, int nu, int nv) {
  std::vector<Vec3> out;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i)
      out.push_back(corner + u * ((i + 0.5) / nu) + v * ((j + 0.5) / nv));
  }
  return out;
}

inline json portal_state(const std::string& portal, const json& fields) {
  return {{"portals", {{portal, fields}}}};
}

struct Comparison {
  double mean = 0, worst = 0;
};

// Relative differences |a − b| / b of the sensors' photometric illuminance.
inline Comparison compare(const std::vector<Rgb>& a, const std::vector<Rgb>& b, const char* what) {
  EXPECT_EQ(a.size(), b.size());
  Comparison c;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const double rel = std::abs(luminance(a[i]) - luminance(b[i])) / luminance(b[i]);
    c.mean += rel / a.size();
    c.worst = std::max(c.worst, rel);
    if (rel > 0.04) {
      std::printf("  %s sensor %zu: %.2f vs reference %.2f lx\n", what, i, luminance(a[i]),
                  luminance(b[i]));
    }
  }
  std::printf("%s: mean relative difference %.4f, worst %.4f\n", what, c.mean, c.worst);
  ::testing::Test::RecordProperty(std::string(what) + "_mean", std::to_string(c.mean));
  ::testing::Test::RecordProperty(std::string(what) + "_worst", std::to_string(c.worst));
  return c;
}

}  // namespace relight::testing
