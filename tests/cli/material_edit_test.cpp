// Live material edits (docs/lighting-state.md "Materials"): a state that changes a wall's albedo
// and makes the floor glossy gives, through `relight probe`, the light of a new precompute of the
// edited scene — within 1 % at every sensor (the acceptance; the difference left is the solver's
// tolerance and the stored SH transfer's own truncation, which both runs share but bounce
// differently) — and a state naming the scene's own materials changes nothing. Sensors on the floor
// and on a wall, a luminaire and a daylit window.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::sensor_lux;
using testing::TempDir;

// The room with `wall` (the +x wall's albedo) and `floor` (the floor material's keys).
std::string room(const std::string& wall, const std::string& floor) {
  return R"({
  "materials": { "white": { "albedo": [0.7, 0.7, 0.7] },
                 "wall": { "albedo": )" +
         wall + R"( },
                 "floor": )" +
         floor + R"(,
                 "glass": { "portal": true } },
  "geometry": [
    { "type": "quad", "corner": [0, 0, 0], "u": [0, 0, 3], "v": [4, 0, 0], "material": "floor" },
    { "type": "quad", "corner": [0, 2.6, 0], "u": [4, 0, 0], "v": [0, 0, 3], "material": "white" },
    { "type": "quad", "corner": [0, 0, 0], "u": [0, 2.6, 0], "v": [0, 0, 3], "material": "white" },
    { "type": "quad", "corner": [4, 0, 0], "u": [0, 0, 3], "v": [0, 2.6, 0], "material": "wall" },
    { "type": "quad", "corner": [0, 0, 3], "u": [0, 2.6, 0], "v": [4, 0, 0], "material": "white" },
    { "type": "quad", "corner": [0, 0, 0], "u": [4, 0, 0], "v": [0, 0.8, 0], "material": "white" },
    { "type": "quad", "corner": [0, 2.2, 0], "u": [4, 0, 0], "v": [0, 0.4, 0], "material": "white" },
    { "type": "quad", "corner": [0, 0.8, 0], "u": [1, 0, 0], "v": [0, 1.4, 0], "material": "white" },
    { "type": "quad", "corner": [3, 0.8, 0], "u": [1, 0, 0], "v": [0, 1.4, 0], "material": "white" },
    { "type": "quad", "corner": [1, 0.8, 0], "u": [2, 0, 0], "v": [0, 1.4, 0], "material": "glass" } ],
  "portals": [ { "name": "south", "materials": ["glass"],
                 "environment": { "type": "uniform", "luminance": 2000 } } ],
  "luminaires": [ { "name": "down", "position": [1.2, 2.5, 2.2],
    "distribution": { "type": "cosine_power", "candela": 900, "exponent": 3 } } ],
  "sensors": [
    { "name": "floor", "grid": { "corner": [0.4, 0.01, 0.4], "u": [3.2, 0, 0], "v": [0, 0, 2.2],
                                 "nu": 4, "nv": 3 } },
    { "name": "ceiling", "normal": [0, -1, 0],
      "grid": { "corner": [0.4, 2.59, 0.4], "u": [3.2, 0, 0], "v": [0, 0, 2.2], "nu": 3, "nv": 2 } },
    { "name": "west", "normal": [1, 0, 0],
      "grid": { "corner": [0.01, 0.5, 0.4], "u": [0, 1.6, 0], "v": [0, 0, 2.2], "nu": 2, "nv": 3 } } ],
  "precompute": { "max_edge": 0.35, "gather_rays": 64, "sensor_gather_rays": 256, "sh_order": 6,
                  "portal_face_size": 8 }
})";
}

class MaterialEdit : public ::testing::Test {
 protected:
  static fs::path precompute(const std::string& name, const std::string& scene) {
    const fs::path json = dir_.path() / (name + ".json"), rlt = dir_.path() / (name + ".rlt");
    std::ofstream(json) << scene;
    const CommandResult r =
        run_relight("precompute '" + json.string() + "' -o '" + rlt.string() + "' --no-progress");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return rlt;
  }
  // Each sensor's lux from `probe` under `state` (the scene's own with an empty state).
  static std::vector<double> lux(const fs::path& rlt, const std::string& state) {
    const fs::path state_file = dir_.path() / "state.json", csv = dir_.path() / "probe.csv";
    std::ofstream(state_file) << state;
    const CommandResult r = run_relight("probe '" + rlt.string() + "' --state '" +
                                        state_file.string() + "' -o '" + csv.string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return sensor_lux(csv);
  }
  static TempDir dir_;
};

TempDir MaterialEdit::dir_;

TEST_F(MaterialEdit, WallColourAndGlossyFloorMatchANewPrecomputeWithinOnePercent) {
  const fs::path base =
      precompute("base", room("[0.6, 0.5, 0.4]", R"({ "albedo": [0.3, 0.3, 0.3] })"));
  const fs::path edited = precompute(
      "edited",
      room("[0.2, 0.3, 0.8]", R"({ "albedo": [0.9, 0.9, 0.9], "metallic": 1, "roughness": 0.3 })"));
  const std::vector<double> expected = lux(edited, "{}");
  const std::vector<double> before = lux(base, "{}");
  const std::vector<double> live =
      lux(base, R"({ "materials": { "wall": { "albedo": [0.2, 0.3, 0.8] },
                     "floor": { "albedo": [0.9, 0.9, 0.9], "metallic": 1, "roughness": 0.3 } } })");
  ASSERT_EQ(expected.size(), 24u);
  ASSERT_EQ(live.size(), expected.size());
  double worst = 0, change = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_GT(expected[i], 0) << i;
    worst = std::max(worst, std::abs(live[i] - expected[i]) / expected[i]);
    change = std::max(change, std::abs(before[i] - expected[i]) / expected[i]);
  }
  std::printf(
      "live edit vs new precompute: worst %.3f %%; the edit changed the light by up to "
      "%.0f %%\n",
      100 * worst, 100 * change);
  EXPECT_LT(worst, 0.01) << "worst relative difference from the new precompute";
  // The edit matters: without it the sensors are far from the edited room's light.
  EXPECT_GT(change, 0.2);
}

TEST_F(MaterialEdit, TheSceneOwnMaterialsSpelledOutChangeNothing) {
  const fs::path base =
      precompute("own", room("[0.6, 0.5, 0.4]", R"({ "albedo": [0.3, 0.3, 0.3] })"));
  const std::vector<double> none = lux(base, "{}");
  const std::vector<double> own =
      lux(base, R"({ "materials": { "wall": { "albedo": [0.6, 0.5, 0.4] } } })");
  ASSERT_EQ(own.size(), none.size());
  for (std::size_t i = 0; i < none.size(); ++i) EXPECT_EQ(own[i], none[i]) << i;
}

}  // namespace
}  // namespace relight
