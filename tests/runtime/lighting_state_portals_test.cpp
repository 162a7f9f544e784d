// The portal and exterior keys of a lighting state (docs/lighting-state.md).
#include <gtest/gtest.h>

#include "common/input_error.h"
#include "runtime/lighting_state.h"
#include "scene/scene_loader.h"
#include "sources/portals/portal_lighting.h"

namespace relight {
namespace {

Scene scene_with_window() {
  return scene_from_json(nlohmann::json::parse(R"({
    "materials": { "wall": { "albedo": [0.5, 0.5, 0.5] },
                   "glass": { "albedo": [0, 0, 0], "portal": true },
                   "skylight": { "albedo": [0, 0, 0], "portal": true } },
    "geometry": [ { "type": "quad", "corner": [0, 1, 5], "u": [0, 1, 0], "v": [1, 0, 0],
                    "material": "glass" } ],
    "portals": [ { "name": "south", "material": "glass", "tint": [0.9, 0.9, 0.9],
                   "environment": { "type": "uniform", "luminance": 1000 } },
                 { "name": "roof", "material": "skylight",
                   "environment": { "type": "uniform", "luminance": 10 } } ],
    "exterior": [ { "name": "bus", "type": "box", "min": [0, 0, 10], "max": [2, 3, 20],
                    "material": "wall" } ]
  })"),
                         "s.json");
}

std::string state_error(const Scene& scene, const char* text) {
  LightingState state = default_lighting_state(scene);
  try {
    apply_lighting_state(state, scene, nlohmann::json::parse(text), "st.json", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LightingStatePortals, DefaultsComeFromTheSceneAndAStateNamesOnlyWhatChanges) {
  const Scene scene = scene_with_window();
  LightingState state = default_lighting_state(scene);
  ASSERT_EQ(state.portals.size(), 2u);
  EXPECT_EQ(state.portals[0].tint, (Rgb{0.9, 0.9, 0.9}));
  ASSERT_EQ(state.portals[0].exterior.size(), 1u);
  apply_lighting_state(state, scene, nlohmann::json::parse(R"({
    "portals": { "south": { "frost_deg": 20, "exterior": { "bus": { "visible": false } },
                            "environment": { "type": "uniform", "luminance": 500 } } },
    "exterior": { "bus": { "translate": [5, 0, 0], "rotate_deg": 90 } }
  })"),
                       "st.json", ".");
  EXPECT_DOUBLE_EQ(state.portals[0].frost_deg, 20);
  EXPECT_DOUBLE_EQ(state.portals[0].environment.luminance, 500);
  EXPECT_EQ(state.portals[0].tint, (Rgb{0.9, 0.9, 0.9}));  // kept
  // The portal's own placement overrides the top-level one for its shell only.
  EXPECT_FALSE(state.portals[0].exterior[0].visible);
  EXPECT_EQ(state.portals[0].exterior[0].translate, (Vec3{5, 0, 0}));
  EXPECT_TRUE(state.portals[1].exterior[0].visible);
  EXPECT_EQ(state.portals[1].exterior[0].translate, (Vec3{5, 0, 0}));
  EXPECT_DOUBLE_EQ(state.portals[1].environment.luminance, 10);
}

TEST(LightingStatePortals, PlacementsMoveAndTurnAboutThePivot) {
  const Scene scene = scene_with_window();
  ExteriorPlacement p;
  p.rotate_deg = 90;
  p.translate = {0, 0, -1};
  const std::vector<ExteriorObject> placed = placed_exterior(scene, {p});
  ASSERT_EQ(placed.size(), 1u);
  // Pivot (1, 1.5, 15); the corner (0, 0, 10) is (−1, ·, −5) from it; turned 90°
  // counter-clockwise seen from above (+x toward −z): (−5, ·, 1), i.e. (−4, 0, 16), then
  // moved to (−4, 0, 15).
  bool found = false;
  for (const Vec3& v : placed[0].positions) found = found || length(v - Vec3{-4, 0, 15}) < 1e-12;
  EXPECT_TRUE(found);
  p.visible = false;
  EXPECT_TRUE(placed_exterior(scene, {p}).empty());
}

TEST(LightingStatePortals, ErrorsNameTheirJsonPath) {
  const Scene scene = scene_with_window();
  EXPECT_NE(state_error(scene, R"({"portals": {"north": {}}})")
                .find("st.json:/portals/north: no portal named \"north\" in the precomputed scene"),
            std::string::npos);
  EXPECT_NE(state_error(scene, R"({"exterior": {"car": {}}})")
                .find("st.json:/exterior/car: no exterior object named \"car\""),
            std::string::npos);
  EXPECT_NE(state_error(scene, R"({"portals": {"south": {"tint": [2, 1, 1]}}})")
                .find("/portals/south/tint: a window's tint is a transmittance"),
            std::string::npos);
  EXPECT_NE(state_error(scene, R"({"portals": {"south": {"glass": 1}}})")
                .find("/portals/south/glass: unknown key"),
            std::string::npos);
  EXPECT_NE(state_error(scene, R"({"exterior": {"bus": {"scale": 2}}})")
                .find("/exterior/bus/scale: unknown key"),
            std::string::npos);
  EXPECT_NE(state_error(scene, R"({"portals": {"south": {"environment": {"type": "cie_sky",
              "sky_type": 12, "horizontal_illuminance": 100}}}})")
                .find("/portals/south/environment"),
            std::string::npos);
}

}  // namespace
}  // namespace relight
