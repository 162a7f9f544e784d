// The relighter keeps one partial sum per kind of source (runtime/relighter.h): whatever
// sequence of changes led to a state, relight() must give what a fresh relighter set to that
// state gives, in both direct modes.
#include <gtest/gtest.h>

#include "light/environment_map_io.h"
#include "runtime/lighting_state.h"
#include "runtime/relighter.h"
#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

using nlohmann::json;

TEST(RelighterPartialSums, AnyOrderOfChangesGivesTheFreshResult) {
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  room.skylight = testing::kSkylight;
  room.albedo = 0.5;
  json doc = testing::window_room_json(room);
  doc["luminaires"] = {{{"name", "lamp"},
                        {"position", {2, 2.5, 2.5}},
                        {"distribution", {{"type", "isotropic"}, {"candela", 200}}}}};
  doc["precompute"] = {{"max_edge", 0.6}, {"gather_rays", 32}, {"sensor_gather_rays", 32}};
  const Scene scene = scene_from_json(doc, "room.json");
  PrecomputeOptions options;
  options.progress = false;
  const Precomputed p = precompute_transfer(scene, options);
  const RelighterSettings settings{};  // the sigma window

  const auto state_of = [&](const char* text) {
    LightingState s = default_lighting_state(scene);
    apply_lighting_state(s, scene, json::parse(text), "s.json", ".");
    return s;
  };
  const LightingState dim = state_of(R"({"luminaires": {"lamp": {"dimmer": 0.3}}})");
  const LightingState dim_sun = state_of(R"({"luminaires": {"lamp": {"dimmer": 0.3}},
    "portals": {"south window": {"environment": {"type": "cie_sky", "sky_type": 12,
      "horizontal_illuminance": 9000, "sun": {"azimuth_deg": 170, "altitude_deg": 40},
      "sun_illuminance": 60000}}}})");
  const LightingState bright_sun = state_of(R"({"luminaires": {"lamp": {"dimmer": 2}},
    "portals": {"south window": {"environment": {"type": "cie_sky", "sky_type": 12,
      "horizontal_illuminance": 9000, "sun": {"azimuth_deg": 170, "altitude_deg": 40},
      "sun_illuminance": 60000}}}})");

  Relighter incremental(in_memory_view(p), scene, settings);
  std::vector<float> out(3 * incremental.receivers()), fresh_out(out.size());
  for (const LightingState* s : {&dim, &dim_sun, &bright_sun, &dim}) {
    incremental.set_state(*s);
    for (bool direct : {true, false}) {
      incremental.relight(out, direct);
      Relighter fresh(in_memory_view(p), scene, settings);
      fresh.set_state(*s);
      fresh.relight(fresh_out, direct);
      for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_NEAR(out[i], fresh_out[i], 1e-5f * std::max(1.0f, std::abs(fresh_out[i])))
            << "receiver value " << i << " direct " << direct;
      }
    }
  }
  // A sky-only change reads the portals' transfer and not the luminaire's.
  incremental.set_state(dim_sun);
  incremental.relight(out);
  incremental.set_state(bright_sun);  // luminaire only
  incremental.relight(out);
  const std::size_t luminaire_frame = incremental.last_frame_bytes();
  incremental.set_state(dim_sun);  // luminaire only
  incremental.relight(out);
  LightingState moved = dim_sun;
  moved.portals[1].environment.sun.azimuth_deg = 180;  // sky only
  incremental.set_state(moved);
  incremental.relight(out);
  const std::size_t sky_frame = incremental.last_frame_bytes();
  EXPECT_EQ(luminaire_frame + sky_frame,
            incremental.transfer_bytes() + 2 * 4 * 3 * incremental.receivers() * sizeof(float));
}

}  // namespace
}  // namespace relight
