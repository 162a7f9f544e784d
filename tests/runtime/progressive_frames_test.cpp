// runtime/progressive_frames.h: a dimmer is shown in one frame, already converged; a repainted
// wall and a moved luminaire in two, the first not converged and different from the second,
// the second equal (0.1% per sensor) to the same state applied to a scene that was never shown
// anything else.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/progressive_frames.h"
#include "support/precomputed_file.h"

namespace relight {
namespace {

nlohmann::json room() {
  return {{"materials",
           {{"grey", {{"albedo", {0.6, 0.5, 0.4}}}}, {"floor", {{"albedo", {0.3, 0.3, 0.3}}}}}},
          {"geometry",
           {{{"type", "box"},
             {"min", {0, 0, 0}},
             {"max", {4, 2.5, 3}},
             {"normals", "inward"},
             {"material", "grey"}},
            {{"type", "quad"},
             {"corner", {0, 0.01, 0}},
             {"u", {0, 0, 3}},
             {"v", {4, 0, 0}},
             {"material", "floor"}}}},
          {"luminaires",
           {{{"name", "down"},
             {"position", {1.2, 2.4, 1.5}},
             {"distribution", {{"type", "cosine_power"}, {"candela", 800}, {"exponent", 2}}}},
            {{"name", "wide"},
             {"position", {2.8, 2.4, 1.5}},
             {"distribution", {{"type", "isotropic"}, {"candela", 200}}}}}},
          {"sensors",
           {{{"name", "work plane"},
             {"grid",
              {{"corner", {0.3, 0.8, 0.3}},
               {"u", {3.4, 0, 0}},
               {"v", {0, 0, 2.4}},
               {"nu", 5},
               {"nv", 4}}}}}},
          {"precompute",
           {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}, {"sh_order", 6}}}};
}

// Shows `state` and returns each frame's `converged` flag and sensor illuminance.
struct Shown {
  std::vector<bool> converged;
  std::vector<std::vector<Rgb>> sensors;
};
Shown show(RelitScene& relit, const LightingState& state) {
  Shown out;
  const int frames = show_progressively(relit, state, [&](bool converged) {
    out.converged.push_back(converged);
    out.sensors.push_back(relit.sensor_irradiance());
  });
  EXPECT_EQ(frames, static_cast<int>(out.converged.size()));
  return out;
}

double worst_difference(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    worst = std::max(worst, std::abs(luminance(a[k]) - luminance(b[k])) / luminance(b[k]));
  }
  return worst;
}

// The sensors of `state` applied to a scene opened for it alone.
std::vector<Rgb> never_shown_anything_else(const std::filesystem::path& rlt,
                                           const LightingState& state) {
  RelitScene fresh(rlt, std::nullopt);
  fresh.apply(state);
  return fresh.sensor_irradiance();
}

TEST(ProgressiveFrames, EditsThatWaitForABounceShowAFirstFrameThenTheConvergedLight) {
  const testing::TempDir dir;
  const auto rlt = testing::write_precomputed(dir, "room", room());
  RelitScene shown(rlt, std::nullopt);
  LightingState state = default_lighting_state(shown.scene());

  state.luminaires[0].dimmer = 0.5;
  const Shown dimmer = show(shown, state);
  EXPECT_EQ(dimmer.converged, std::vector<bool>{true});

  for (Material& m : state.materials) {
    if (m.name == "grey") m.albedo = m.albedo * 0.5;
  }
  const Shown repainted = show(shown, state);
  ASSERT_EQ(repainted.converged, (std::vector<bool>{false, true}));
  EXPECT_GT(worst_difference(repainted.sensors[0], repainted.sensors[1]), 1e-3);
  EXPECT_LT(worst_difference(repainted.sensors[1], never_shown_anything_else(rlt, state)), 1e-3);

  state.luminaires[0].position.x += 0.6;
  const Shown moved = show(shown, state);
  ASSERT_EQ(moved.converged, (std::vector<bool>{false, true}));
  EXPECT_GT(worst_difference(moved.sensors[0], moved.sensors[1]), 1e-4);
  EXPECT_LT(worst_difference(moved.sensors[1], never_shown_anything_else(rlt, state)), 1e-3);
}

}  // namespace
}  // namespace relight
