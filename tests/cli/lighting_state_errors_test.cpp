// Lighting-state files (docs/lighting-state.md) as `probe` and `render` read them: every
// bad file exits 2 with exactly one line "error: STATEFILE:/json/pointer: reason" (or
// STATEFILE:LINE for malformed JSON), and a state using every key is accepted and does
// what the documentation says. One tiny room is precomputed once for the whole suite.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

const char* kRoom = R"({
  "materials": { "white": { "albedo": [0.6, 0.6, 0.6] } },
  "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward",
                  "material": "white" } ],
  "luminaires": [
    { "name": "down", "position": [1.5, 2.4, 1.5],
      "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } },
    { "name": "spot", "position": [0.5, 2.0, 0.5], "aim": [0, -1, 0], "color": [1, 0.9, 0.8],
      "dimmer": 0.8, "distribution": { "type": "isotropic", "candela": 50 } } ],
  "sensors": [ { "name": "floor", "grid": { "corner": [0.25, 0, 0.25], "u": [2.5, 0, 0],
                                            "v": [0, 0, 2.5], "nu": 4, "nv": 4 } } ],
  "cameras": [ { "name": "inside", "eye": [1.5, 1.2, 2.9], "target": [1.5, 1, 0] } ],
  "precompute": { "max_edge": 0.5, "gather_rays": 32, "sh_order": 4 }
})";

constexpr std::size_t kSensors = 16;

class LightingStateFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    const auto scene = dir_->write("room.json", kRoom);
    rlt_ = dir_->path() / "room.rlt";
    precompute_exit_ =
        run_relight("precompute '" + scene.string() + "' -o '" + rlt_.string() + "' --no-progress")
            .exit_code;
    // Photometry files beside the state files, referred to by relative paths.
    fs::create_directories(dir_->path() / "states" / "photometry");
    for (const char* f : {"small_axial.ldt", "bilateral_90_270_2019.ies"}) {
      fs::copy_file(fs::path(RELIGHT_TEST_DATA) / "photometry" / f,
                    dir_->path() / "states" / "photometry" / f);
    }
  }
  static void TearDownTestSuite() { dir_.reset(); }
  void SetUp() override { ASSERT_EQ(precompute_exit_, 0); }

  // Writes the state into states/NAME and runs probe with it.
  static CommandResult probe(const std::string& name, const std::string& state,
                             const fs::path& csv = {}) {
    const fs::path file = dir_->path() / "states" / name;
    std::ofstream(file, std::ios::binary) << state;
    std::string args = "probe '" + rlt_.string() + "' --state '" + file.string() + "'";
    if (!csv.empty()) args += " -o '" + csv.string() + "'";
    return run_relight(args);
  }
  static fs::path state_path(const std::string& name) { return dir_->path() / "states" / name; }

  // Exit 2 with exactly the one line "error: STATEFILE" + where + ": " + reason_prefix...
  static void expect_state_error(const std::string& name, const std::string& state,
                                 const std::string& where, const std::string& reason) {
    const CommandResult r = probe(name, state);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const std::string prefix = "error: " + state_path(name).string() + where + ": " + reason;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << "expected: " << prefix << "\n     got: " << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }

  // Floor lux of probe under a state.
  static std::vector<double> lux(const std::string& name, const std::string& state) {
    const fs::path csv = dir_->path() / (name + ".csv");
    const CommandResult r = probe(name, state, csv);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::vector<double> out;
    std::istringstream in(read_text(csv));
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::istringstream l(line);
      std::string cell;
      for (int i = 0; i <= 8; ++i) std::getline(l, cell, ',');
      out.push_back(std::stod(cell));
    }
    EXPECT_EQ(out.size(), kSensors);
    return out;
  }

  static std::unique_ptr<TempDir> dir_;
  static fs::path rlt_;
  static int precompute_exit_;
};

std::unique_ptr<TempDir> LightingStateFiles::dir_;
fs::path LightingStateFiles::rlt_;
int LightingStateFiles::precompute_exit_ = -1;

TEST_F(LightingStateFiles, UnknownLuminaireName) {
  expect_state_error("unknown-luminaire.json", R"({ "luminaires": { "desk": { "dimmer": 1 } } })",
                     ":/luminaires/desk", "no luminaire named \"desk\" in the precomputed scene");
}

TEST_F(LightingStateFiles, UnknownKey) {
  expect_state_error("unknown-key.json",
                     R"({ "luminaires": { "down": { "dimmer": 1, "brightness": 2 } } })",
                     ":/luminaires/down/brightness",
                     "unknown key \"brightness\" (expected one of: on, dimmer, color, cct_kelvin, "
                     "aim, target, c0, distribution, position, size)");
  // At the top level: exit 2, one line, naming the key (the exact pointer is checked by
  // UnknownTopLevelKeyHasTheRootPointer below).
  const CommandResult top = probe("unknown-top.json", R"({ "lights": {} })");
  EXPECT_EQ(top.exit_code, 2);
  EXPECT_EQ(top.err.rfind("error: " + state_path("unknown-top.json").string() + ":", 0), 0u)
      << top.err;
  EXPECT_NE(top.err.find("lights: unknown key \"lights\" (expected one of: luminaires, portals, "
                         "exterior, emitters, objects, materials, environment, site)\n"),
            std::string::npos)
      << top.err;
  EXPECT_EQ(top.err.find('\n'), top.err.size() - 1) << top.err;
  expect_state_error("unknown-distribution-key.json",
                     R"({ "luminaires": { "down": { "distribution":
                          { "type": "isotropic", "candela": 10, "lumens": 100 } } } })",
                     ":/luminaires/down/distribution/lumens", "unknown key \"lumens\"");
}

// JsonNode::expect_keys (src/scene/json_node.cpp) builds the child pointer from where()
// ("FILE:/" at the root) rather than from the pointer, so an unknown top-level key is
// reported as "FILE://lights" instead of "FILE:/lights" (scene files alike). Enable once
// fixed.
TEST_F(LightingStateFiles, UnknownTopLevelKeyHasTheRootPointer) {
  expect_state_error(
      "unknown-top-key.json", R"({ "lights": {} })", ":/lights",
      "unknown key \"lights\" (expected one of: luminaires, portals, exterior, emitters, objects, "
      "materials, environment, site)");
}

TEST_F(LightingStateFiles, MovingALuminaireOutsideTheSceneIsRefused) {
  const CommandResult r =
      probe("moved.json", R"({ "luminaires": { "down": { "position": [1.5, 9, 1.6] } } })");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("moved.json:luminaires.down.position: outside the scene"), std::string::npos)
      << r.err;
  // Its own position, and one inside the room, load.
  const CommandResult same = probe(
      "same-position.json", R"({ "luminaires": { "down": { "position": [1.5, 2.4, 1.5] } } })");
  EXPECT_EQ(same.exit_code, 0) << same.err;
  const CommandResult inside =
      probe("inside.json", R"({ "luminaires": { "down": { "position": [1.5, 2.4, 1.6] } } })");
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
}

TEST_F(LightingStateFiles, ColourTemperatureOutOfRange) {
  for (const char* k : {"1000", "1666", "25001", "60000", "-3"}) {
    expect_state_error(std::string("cct-") + k + ".json",
                       std::string(R"({ "luminaires": { "down": { "cct_kelvin": )") + k + "} } }",
                       ":/luminaires/down/cct_kelvin",
                       "colour temperature must lie in 1667..25000 K");
  }
  // The ends of the range are accepted.
  for (const char* k : {"1667", "25000"}) {
    const CommandResult r =
        probe(std::string("cct-ok-") + k + ".json",
              std::string(R"({ "luminaires": { "down": { "cct_kelvin": )") + k + "} } }");
    EXPECT_EQ(r.exit_code, 0) << k << ": " << r.err;
  }
  expect_state_error("cct-string.json",
                     R"({ "luminaires": { "down": { "cct_kelvin": "3000K" } } })",
                     ":/luminaires/down/cct_kelvin", "expected a number");
}

TEST_F(LightingStateFiles, ColorAndCctTogether) {
  expect_state_error("both-colours.json",
                     R"({ "luminaires": { "spot": { "color": [1, 1, 1], "cct_kelvin": 3000 } } })",
                     ":/luminaires/spot", "give either color or cct_kelvin");
}

TEST_F(LightingStateFiles, MalformedJsonNamesTheLine) {
  expect_state_error("malformed.json",
                     "{\n  \"luminaires\": {\n    \"down\": { \"dimmer\": 0.5, }\n  }\n}\n", ":3",
                     "malformed JSON: ");
}

TEST_F(LightingStateFiles, UnknownDistributionType) {
  expect_state_error("laser.json",
                     R"({ "luminaires": { "down": { "distribution": { "type": "laser" } } } })",
                     ":/luminaires/down/distribution/type",
                     "unknown distribution type \"laser\" (expected isotropic, cosine_power, "
                     "curve, ies or ldt)");
}

TEST_F(LightingStateFiles, OtherBadValues) {
  expect_state_error("negative-dimmer.json", R"({ "luminaires": { "down": { "dimmer": -0.1 } } })",
                     ":/luminaires/down/dimmer", "must be at least 0, got -0.1");
  expect_state_error("on-string.json", R"({ "luminaires": { "down": { "on": "yes" } } })",
                     ":/luminaires/down/on", "expected true or false");
  expect_state_error("black.json", R"({ "luminaires": { "down": { "color": [0, 0, 0] } } })",
                     ":/luminaires/down/color", "colour must have a positive luminance");
  expect_state_error("negative-colour.json",
                     R"({ "luminaires": { "down": { "color": [1, -1, 1] } } })",
                     ":/luminaires/down/color", "colour components must not be negative");
  expect_state_error("aim-and-target.json",
                     R"({ "luminaires": { "down": { "aim": [0, -1, 0], "target": [1, 0, 1] } } })",
                     ":/luminaires/down", "give either aim or target");
  expect_state_error("zero-aim.json", R"({ "luminaires": { "down": { "aim": [0, 0, 0] } } })",
                     ":/luminaires/down/aim", "direction must not be zero");
  expect_state_error("target-at-luminaire.json",
                     R"({ "luminaires": { "down": { "target": [1.5, 2.4, 1.5] } } })",
                     ":/luminaires/down/target", "target coincides with the luminaire");
  expect_state_error("c0-along-aim.json",
                     R"({ "luminaires": { "down": { "aim": [1, 0, 0], "c0": [-2, 0, 0] } } })",
                     ":/luminaires/down/c0", "c0 must not be parallel to aim");
  expect_state_error("luminaires-array.json", R"({ "luminaires": [ { "down": {} } ] })",
                     ":/luminaires", "expected an object mapping luminaire names to states");
  expect_state_error("luminaire-number.json", R"({ "luminaires": { "down": 0.5 } })",
                     ":/luminaires/down", "expected an object");
  expect_state_error("not-an-object.json", "[1, 2]", ":/", "expected an object");
  expect_state_error("curve-short.json",
                     R"({ "luminaires": { "down": { "distribution":
                          { "type": "curve", "gamma_deg": [0, 90], "candela": [10] } } } })",
                     ":/luminaires/down/distribution/candela",
                     "expected as many values as gamma_deg (2)");
  // Relative photometry files resolve against the state file's folder.
  expect_state_error(
      "missing-ies.json",
      R"({ "luminaires": { "down": { "distribution":
                          { "type": "ies", "file": "photometry/absent.ies" } } } })",
      ":/luminaires/down/distribution/file",
      "file not found: " + (dir_->path() / "states" / "photometry" / "absent.ies").string());
  // A missing state file.
  const CommandResult r = run_relight("probe '" + rlt_.string() + "' --state '" +
                                      state_path("absent.json").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "error: " + state_path("absent.json").string() + ": cannot open file: no such file\n");
}

TEST_F(LightingStateFiles, BadMaterialEdits) {
  expect_state_error("unknown-material.json",
                     R"({ "materials": { "marble": { "albedo": [0.5, 0.5, 0.5] } } })",
                     ":/materials/marble", "no material named \"marble\" in the precomputed scene");
  expect_state_error("rough-material.json", R"({ "materials": { "white": { "roughness": 1.5 } } })",
                     ":/materials/white/roughness", "must be between 0 and 1, got 1.5");
  expect_state_error("metal-material.json", R"({ "materials": { "white": { "metallic": -0.1 } } })",
                     ":/materials/white/metallic", "must be between 0 and 1, got -0.1");
  expect_state_error("bright-material.json",
                     R"({ "materials": { "white": { "albedo": [0.5, 1.2, 0.5] } } })",
                     ":/materials/white/albedo", "");
  expect_state_error("material-key.json", R"({ "materials": { "white": { "portal": true } } })",
                     ":/materials/white/portal", "unknown key \"portal\"");
  expect_state_error("materials-array.json", R"({ "materials": [ "white" ] })", ":/materials",
                     "expected an object mapping material names to materials");
}

TEST_F(LightingStateFiles, RenderReportsStateErrorsToo) {
  const fs::path state = state_path("render-bad.json");
  std::ofstream(state) << R"({ "luminaires": { "down": { "dimmer": "full" } } })";
  const CommandResult r =
      run_relight("render '" + rlt_.string() + "' --state '" + state.string() +
                  "' --width 8 --height 8 -o '" + (dir_->path() / "x.png").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + state.string() + ":/luminaires/down/dimmer: expected a number\n");
  EXPECT_FALSE(fs::exists(dir_->path() / "x.png"));
}

TEST_F(LightingStateFiles, GoodStateUsingEveryKey) {
  const auto base = lux("empty.json", "{}");
  // Every key; the analytic distribution types in turn, then the two file types.
  const char* distributions[] = {
      R"({ "type": "isotropic", "candela": 120 })",
      R"({ "type": "cosine_power", "candela": 900, "exponent": 8, "cutoff_deg": 50 })",
      R"({ "type": "curve", "gamma_deg": [0, 30, 60, 90], "candela": [400, 300, 100, 0] })",
      R"({ "type": "ies", "file": "photometry/bilateral_90_270_2019.ies" })",
      R"({ "type": "ldt", "file": "photometry/small_axial.ldt" })"};
  int n = 0;
  for (const char* d : distributions) {
    const std::string state = std::string(R"({ "luminaires": {
      "down": { "on": true, "dimmer": 0.7, "cct_kelvin": 3000, "aim": [0.2, -1, 0.1],
                "c0": [0, 0, 1], "position": [1.5, 2.4, 1.5], "distribution": )") +
                              d + R"( },
      "spot": { "on": true, "dimmer": 1.5, "color": [0.8, 0.9, 1], "target": [2, 0, 2],
                "c0": [1, 0, 0] } } })";
    const std::string name = "every-key-" + std::to_string(n++);
    const auto e = lux(name + ".json", state);
    ASSERT_EQ(e.size(), kSensors) << d;
    double changed = 0;
    for (std::size_t i = 0; i < kSensors; ++i) {
      EXPECT_GT(e[i], 0) << d << " sensor " << i;
      changed = std::max(changed, std::abs(e[i] - base[i]) / base[i]);
    }
    EXPECT_GT(changed, 0.01) << d;
    // render takes the same state.
    const CommandResult r = run_relight(
        "render '" + rlt_.string() + "' --state '" + state_path(name + ".json").string() +
        "' --width 16 --height 12 -o '" + (dir_->path() / (name + ".png")).string() + "'");
    EXPECT_EQ(r.exit_code, 0) << d << ": " << r.err;
  }
}

TEST_F(LightingStateFiles, StateAppliesOnTopOfTheScene) {
  const auto none = lux("none.json", "{}");
  const auto also_none = lux("no-luminaires.json", R"({ "luminaires": {} })");
  // The scene's own values, spelled out, change nothing.
  const auto own = lux("own.json", R"({ "luminaires": {
      "down": { "on": true, "dimmer": 1, "color": [1, 1, 1], "aim": [0, -1, 0], "c0": [1, 0, 0],
                "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } },
      "spot": { "dimmer": 0.8, "color": [1, 0.9, 0.8] } } })");
  ASSERT_EQ(none.size(), kSensors);
  for (std::size_t i = 0; i < kSensors; ++i) {
    EXPECT_EQ(also_none[i], none[i]) << i;
    EXPECT_NEAR(own[i], none[i], 1e-5 * none[i]) << i;
  }
}

TEST_F(LightingStateFiles, TargetAimsAtAPoint) {
  // "target" straight below the luminaire is "aim" [0, -1, 0], the scene's own aim.
  const auto base = lux("t-base.json", "{}");
  const auto below =
      lux("t-below.json", R"({ "luminaires": { "down": { "target": [1.5, 0, 1.5] } } })");
  // Aiming at a point equals aiming along the direction to it.
  const auto at_point =
      lux("t-point.json", R"({ "luminaires": { "down": { "target": [0, 0.9, 1.5] } } })");
  const auto along =
      lux("t-along.json", R"({ "luminaires": { "down": { "aim": [-1.5, -1.5, 0] } } })");
  for (std::size_t i = 0; i < kSensors; ++i) {
    EXPECT_NEAR(below[i], base[i], 1e-5 * base[i]) << i;
    EXPECT_NEAR(at_point[i], along[i], 1e-5 * along[i]) << i;
  }
  // Turned toward the wall, the downlight lights the floor grid far less on average.
  double sum_base = 0, sum_wall = 0;
  for (std::size_t i = 0; i < kSensors; ++i) {
    sum_base += base[i];
    sum_wall += at_point[i];
  }
  EXPECT_LT(sum_wall, 0.8 * sum_base);
}

TEST_F(LightingStateFiles, C0IsReorthogonalisedToTheAim) {
  // An asymmetric (bilateral) IES distribution, so the C0 direction matters.
  const std::string ies =
      R"("distribution": { "type": "ies", "file": "photometry/bilateral_90_270_2019.ies" })";
  const auto c0_x =
      lux("c0-x.json", R"({ "luminaires": { "down": { "c0": [1, 0, 0], )" + ies + "} } }");
  const auto c0_tilted =
      lux("c0-tilted.json", R"({ "luminaires": { "down": { "c0": [1, 0.7, 0], )" + ies + "} } }");
  const auto c0_z =
      lux("c0-z.json", R"({ "luminaires": { "down": { "c0": [0, 0, 1], )" + ies + "} } }");
  double differs = 0;
  for (std::size_t i = 0; i < kSensors; ++i) {
    // c0 [1, 0.7, 0] loses its component along aim [0, -1, 0]: it is [1, 0, 0].
    EXPECT_NEAR(c0_tilted[i], c0_x[i], 1e-5 * c0_x[i]) << i;
    differs = std::max(differs, std::abs(c0_z[i] - c0_x[i]) / c0_x[i]);
  }
  EXPECT_GT(differs, 0.01);  // turning C0 by 90° does change the light
}

TEST_F(LightingStateFiles, DistributionIsLinearInCandela) {
  const auto a = lux("iso-200.json", R"({ "luminaires": { "down": { "distribution":
                                         { "type": "isotropic", "candela": 200 } } } })");
  const auto b = lux("iso-100x2.json", R"({ "luminaires": { "down": { "dimmer": 2, "distribution":
                                         { "type": "isotropic", "candela": 100 } } } })");
  for (std::size_t i = 0; i < kSensors; ++i) EXPECT_NEAR(a[i], b[i], 1e-5 * a[i]) << i;
}

}  // namespace
}  // namespace relight
