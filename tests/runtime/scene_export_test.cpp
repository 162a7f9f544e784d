// The scene a state's layout makes (runtime/scene_export.h): the state's luminaires as ordinary
// ones — moved, re-aimed, added after the scene's, switched-off ones left out — and every
// relative file path absolute, so that the exported file loads from any folder into the same
// luminaires (positions and directions exact to 1e-12).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "runtime/lighting_state.h"
#include "runtime/scene_export.h"
#include "scene/scene_loader.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

std::string flat_ies() {
  std::ostringstream s;
  s << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 1 1 2 0.1 0.1 0\n1 1 10\n0 45 90\n0\n"
       "300 200 0\n";
  return s.str();
}

void expect_near(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(SceneExport, TheLayoutBecomesOrdinaryLuminairesWithAbsoluteFiles) {
  const testing::TempDir dir;
  fs::create_directories(dir.path() / "lamps");
  dir.write("lamps/flat.ies", flat_ies());
  const nlohmann::json scene_json = nlohmann::json::parse(R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [4, 3, 4], "normals": "inward",
                    "material": "grey" } ],
    "luminaires": [
      { "name": "down", "position": [1, 2.9, 1],
        "distribution": { "type": "cosine_power", "candela": 800, "exponent": 2 } },
      { "name": "spot", "position": [3, 2.9, 3],
        "distribution": { "type": "ies", "file": "lamps/flat.ies" } } ]
  })");
  const fs::path scene_file = dir.path() / "room.json";
  const Scene scene = scene_from_json(scene_json, scene_file);
  LightingState state = default_lighting_state(scene);
  apply_lighting_state(state, scene, nlohmann::json::parse(R"({"luminaires": {
      "down": {"position": [1.5, 2.9, 2], "target": [2, 0, 2], "dimmer": 0.5},
      "spot": {"on": false},
      "added": {"position": [2, 2.8, 3], "distribution": {"type": "ies", "file": "lamps/flat.ies"},
                "cct_kelvin": 3000, "size": [0.2, 0.2, 0]} }})"),
                       "state.json", dir.path());

  const nlohmann::json exported = scene_json_with_layout(scene_json, scene_file, state);
  ASSERT_EQ(exported.at("luminaires").size(), 2u);
  EXPECT_EQ(exported.at("luminaires")[0].at("name"), "down");
  EXPECT_EQ(exported.at("luminaires")[1].at("name"), "added");
  EXPECT_EQ(exported.at("luminaires")[1].at("distribution").at("file"),
            (dir.path() / "lamps" / "flat.ies").string());
  EXPECT_EQ(exported.at("geometry"), scene_json.at("geometry"));

  // Loaded from another folder, it is the state's layout.
  const Scene again = scene_from_json(exported, "/elsewhere/exported.json");
  ASSERT_EQ(again.luminaires.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const LuminaireState& s = state.luminaires[k == 0 ? 0 : 2];
    const Luminaire& l = again.luminaires[k];
    EXPECT_EQ(l.name, s.name);
    expect_near(l.position, s.position);
    expect_near(l.aim, s.aim);
    expect_near(l.c0, s.c0);
    EXPECT_NEAR(l.dimmer, s.dimmer, 1e-12);
    EXPECT_NEAR(l.color.r, s.color.r, 1e-12);
    EXPECT_NEAR(l.color.b, s.color.b, 1e-12);
    EXPECT_EQ(l.distribution.type, s.distribution.type);
    EXPECT_EQ(l.has_size, s.has_size);
  }
  EXPECT_NEAR(again.luminaires[0].dimmer, 0.5, 1e-12);
  EXPECT_NEAR(again.luminaires[0].distribution.exponent, 2.0, 1e-12);
}

TEST(SceneExport, RelativeFilesAnywhereInTheSceneBecomeAbsolute) {
  const nlohmann::json scene_json = nlohmann::json::parse(R"({
    "geometry": [ { "type": "mesh", "file": "meshes/room.obj" },
                  { "type": "mesh", "file": "/abs/chair.obj" } ],
    "environment": { "type": "map", "file": "sky.exr" }, "luminaires": [] })");
  const nlohmann::json exported =
      scene_json_with_layout(scene_json, "/projects/a/scene.json", LightingState{});
  EXPECT_EQ(exported.at("geometry")[0].at("file"), "/projects/a/meshes/room.obj");
  EXPECT_EQ(exported.at("geometry")[1].at("file"), "/abs/chair.obj");
  EXPECT_EQ(exported.at("environment").at("file"), "/projects/a/sky.exr");
}

}  // namespace
}  // namespace relight
