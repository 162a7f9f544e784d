// Near-field emitters in every output, as a user runs them:
//  * probe and the reference against the closed form of a small far emitter, I·cosθ/d²: 0.5 %;
//  * a panel 0.4 m over a table: probe within 2 % mean and 6 % worst of the reference
//    (65,536 spp) on the table, the work plane and the ceiling (which only interreflection
//    lights), in the scene's state and after the state moves the panel;
//  * render shows them (vertex and per-pixel direct), the reference honours --state, and bad
//    emitter states are refused with their JSON path.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_exr.h"
#include "math/vec3.h"
#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::expect_input_error;
using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

// lux per sensor set, in file order.
std::map<std::string, std::vector<double>> sensor_lux(const fs::path& csv) {
  std::map<std::string, std::vector<double>> out;
  const auto rows = parse_csv(read_text(csv));
  for (std::size_t i = 1; i < rows.size(); ++i)
    out[rows[i].at(0)].push_back(std::stod(rows[i].at(8)));
  return out;
}

const char* kTableRoom = R"({
  "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] }, "wood": { "albedo": [0.5, 0.35, 0.2] } },
  "geometry": [
    { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward", "material": "grey" },
    { "type": "box", "min": [1, 0, 1], "max": [2, 0.75, 2], "material": "wood" } ],
  "emitters": [
    { "name": "panel", "geometry": { "type": "quad", "corner": [1.3, 1.15, 1.3], "u": [0.4, 0, 0],
                                     "v": [0, 0, 0.4] }, "luminance": 5000, "color": [1, 0.9, 0.8] } ],
  "sensors": [
    { "name": "table", "grid": { "corner": [1.05, 0.751, 1.05], "u": [0.9, 0, 0], "v": [0, 0, 0.9],
                                 "nu": 9, "nv": 9 } },
    { "name": "work plane", "grid": { "corner": [0.25, 0.8, 0.25], "u": [2.5, 0, 0],
                                      "v": [0, 0, 2.5], "nu": 10, "nv": 10 } },
    { "name": "ceiling", "grid": { "corner": [0.25, 2.499, 0.25], "u": [2.5, 0, 0], "v": [0, 0, 2.5],
                                   "nu": 8, "nv": 8 }, "normal": [0, -1, 0] } ],
  "cameras": [ { "name": "in", "eye": [1.5, 1.8, 2.9], "target": [1.5, 0.6, 1.5] } ],
  "precompute": { "gather_rays": 64, "nearfield_interreflection": true }
})";

class EmitterOutputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    const fs::path scene = dir_->write("room.json", kTableRoom);
    const auto r = run_relight("precompute '" + scene.string() + "' -o '" + rlt().string() +
                               "' --no-progress");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { dir_.reset(); }
  static fs::path scene() { return dir_->path() / "room.json"; }
  static fs::path rlt() { return dir_->path() / "room.rlt"; }
  static fs::path file(const std::string& name) { return dir_->path() / name; }
  static std::unique_ptr<TempDir> dir_;  // one precompute for the suite
};
std::unique_ptr<TempDir> EmitterOutputs::dir_;

// Probe and reference (same state) agree per sensor set within the bounds above.
void expect_probe_matches_reference(const fs::path& rlt, const fs::path& scene,
                                    const std::string& state, const fs::path& dir,
                                    const std::string& name) {
  const std::string state_arg = state.empty() ? "" : " --state '" + state + "'";
  const fs::path probe = dir / (name + "-probe.csv"), ref = dir / (name + "-reference.csv");
  const auto p =
      run_relight("probe '" + rlt.string() + "'" + state_arg + " -o '" + probe.string() + "'");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto r = run_relight("reference '" + scene.string() + "'" + state_arg +
                             " --spp 65536 --no-progress --sensors-out '" + ref.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto got = sensor_lux(probe), want = sensor_lux(ref);
  ASSERT_EQ(got.size(), 3u);
  for (const auto& [set, values] : got) {
    const std::vector<double>& expected = want.at(set);
    ASSERT_EQ(values.size(), expected.size());
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      ASSERT_GT(expected[i], 0) << set << " " << i;
      const double e = std::abs(values[i] / expected[i] - 1);
      sum += e;
      worst = std::max(worst, e);
    }
    const double mean = sum / static_cast<double>(values.size());
    std::printf("%s, %s: probe vs reference mean |Δ| %.2f %%, worst %.2f %%\n", name.c_str(),
                set.c_str(), 100 * mean, 100 * worst);
    EXPECT_LT(mean, 0.02) << name << " " << set;
    EXPECT_LT(worst, 0.06) << name << " " << set;
  }
}

TEST_F(EmitterOutputs, ProbeMatchesTheReferenceOverTableWorkPlaneAndCeiling) {
  expect_probe_matches_reference(rlt(), scene(), "", dir_->path(), "scene state");
}

TEST_F(EmitterOutputs, ProbeMatchesTheReferenceAfterTheStateMovesThePanel) {
  const fs::path moved = dir_->write(
      "moved.json", R"({"emitters": {"panel": {"translate": [0.3, -0.05, -0.2], "rotate_deg": 30,
                                               "luminance": 8000}}})");
  expect_probe_matches_reference(rlt(), scene(), moved.string(), dir_->path(), "moved");
}

TEST_F(EmitterOutputs, RenderShowsTheEmitterInVertexAndPixelModes) {
  const fs::path off = dir_->write("off.json", R"({"emitters": {"panel": {"on": false}}})");
  for (const char* mode : {"vertex", "pixel"}) {
    double mean[2] = {0, 0};
    for (int lit = 0; lit < 2; ++lit) {
      const fs::path image = file(std::string("view-") + mode + (lit ? "-on" : "-off") + ".exr");
      const auto r =
          run_relight("render '" + rlt().string() + "'" +
                      (lit ? std::string() : " --state '" + off.string() + "'") +
                      " --width 48 --height 32 --direct " + mode + " -o '" + image.string() + "'");
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const Image img = read_exr(image);
      for (const Rgb& p : img.pixels) mean[lit] += std::isfinite(p.g) ? p.g : 0;
      mean[lit] /= static_cast<double>(img.pixels.size());
    }
    std::printf("render --direct %s: mean luminance off %.3g, on %.3g cd/m2\n", mode, mean[0],
                mean[1]);
    EXPECT_EQ(mean[0], 0) << mode;
    EXPECT_GT(mean[1], 10) << mode;
  }
}

TEST_F(EmitterOutputs, BadEmitterStatesAreRefusedWithTheirJsonPath) {
  const fs::path unknown = dir_->write("unknown.json", R"({"emitters": {"lamp": {"on": true}}})");
  // JSON has no NaN: an overflowing number and a string "NaN" are what a user can write.
  const fs::path huge =
      dir_->write("huge.json", R"({"emitters": {"panel": {"translate": [1e999, 0, 0]}}})");
  const fs::path nan = dir_->write("nan.json", R"({"emitters": {"panel": {"rotate_deg": "NaN"}}})");
  for (const std::string& command :
       {"probe '" + rlt().string() + "'",
        "render '" + rlt().string() + "' -o '" + file("x.png").string() + "'",
        "reference '" + scene().string() + "' --spp 1 --no-progress"}) {
    expect_input_error(run_relight(command + " --state '" + unknown.string() + "'"),
                       unknown.string() + ":/emitters/lamp: no emitter named \"lamp\"");
    expect_input_error(run_relight(command + " --state '" + huge.string() + "'"),
                       huge.string() + ":1: malformed JSON: number out of range");
    expect_input_error(run_relight(command + " --state '" + nan.string() + "'"),
                       nan.string() + ":/emitters/panel/rotate_deg: expected a number");
  }
}

// A 5 cm square 2.5 m above sensors in a black room: E = L·A·cos θ·cos θ' / d², the far-field
// (I/d²) closed form, within 0.5 % for probe and reference.
TEST(EmitterClosedForm, ASmallFarEmitterIsIOverDSquaredInProbeAndReference) {
  const TempDir dir;
  const fs::path scene = dir.write("far.json", R"({
    "materials": { "black": { "albedo": [0, 0, 0] } },
    "geometry": [ { "type": "box", "min": [-3, 0, -3], "max": [3, 3, 3], "normals": "inward",
                    "material": "black" } ],
    "emitters": [ { "name": "dot", "geometry": { "type": "quad", "corner": [-0.025, 2.5, -0.025],
                    "u": [0.05, 0, 0], "v": [0, 0, 0.05] }, "luminance": 1e6 } ],
    "sensors": [ { "name": "floor", "points": [[0, 0.001, 0], [0.5, 0.001, 0], [1, 0.001, 1],
                                               [-1.5, 0.001, 0.5]] } ]
  })");
  const fs::path rlt = dir.path() / "far.rlt", probe = dir.path() / "probe.csv",
                 ref = dir.path() / "ref.csv";
  ASSERT_EQ(
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress")
          .exit_code,
      0);
  ASSERT_EQ(run_relight("probe '" + rlt.string() + "' -o '" + probe.string() + "'").exit_code, 0);
  ASSERT_EQ(run_relight("reference '" + scene.string() +
                        "' --spp 1024 --no-progress --sensors-out '" + ref.string() + "'")
                .exit_code,
            0);
  const double intensity = 1e6 * 0.05 * 0.05;  // cd toward the normal
  const std::vector<Vec3> points{{0, 0, 0}, {0.5, 0, 0}, {1, 0, 1}, {-1.5, 0, 0.5}};
  const auto got = sensor_lux(probe).at("floor"), traced = sensor_lux(ref).at("floor");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = Vec3{0, 2.5, 0} - (points[i] + Vec3{0, 0.001, 0});
    const double r2 = dot(d, d), c = d.y / std::sqrt(r2);
    const double expected = intensity * c * c / r2;  // cos θ at both ends
    std::printf("far emitter, sensor %zu: closed form %.4f lx, probe %.4f, reference %.4f\n", i,
                expected, got[i], traced[i]);
    EXPECT_NEAR(got[i] / expected, 1, 0.005) << i;
    EXPECT_NEAR(traced[i] / expected, 1, 0.005) << i;
  }
}

// The reference honours a whole lighting state: a luminaire dimmed to 0.3 and turned, a window's
// sky and tint, an emitter switched off; with the same seed every path is the same, so the
// luminaire-only readings scale by exactly the dimmer.
TEST(ReferenceState, TheReferenceTracesTheSceneUnderAState) {
  const TempDir dir;
  const fs::path scene = dir.write("lit.json", R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward",
                    "material": "grey" } ],
    "luminaires": [ { "name": "down", "position": [1.5, 2.4, 1.5],
                      "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } } ],
    "emitters": [ { "name": "glow", "geometry": { "type": "quad", "corner": [0.5, 2, 0.5],
                    "u": [0.2, 0, 0], "v": [0, 0, 0.2] }, "luminance": 2000 } ],
    "sensors": [ { "name": "floor", "grid": { "corner": [0.5, 0, 0.5], "u": [2, 0, 0],
                   "v": [0, 0, 2], "nu": 2, "nv": 3 } } ]
  })");
  const fs::path dim = dir.write("dim.json", R"({"luminaires": {"down": {"dimmer": 0.3}},
                                                 "emitters": {"glow": {"on": false}}})");
  const fs::path dark = dir.write("dark.json", R"({"luminaires": {"down": {"on": false}},
                                                  "emitters": {"glow": {"on": false}}})");
  const auto run = [&](const std::string& state, const std::string& out) {
    const fs::path csv = dir.path() / out;
    const auto r = run_relight("reference '" + scene.string() + "' --spp 256 --no-progress" +
                               (state.empty() ? "" : " --state '" + state + "'") +
                               " --sensors-out '" + csv.string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return sensor_lux(csv).at("floor");
  };
  const auto all = run("", "all.csv"), dimmed = run(dim.string(), "dim.csv"),
             none = run(dark.string(), "dark.csv");
  const auto full =
      run(dir.write("only.json", R"({"emitters": {"glow": {"on": false}}})").string(), "only.csv");
  for (std::size_t i = 0; i < full.size(); ++i) {
    EXPECT_NEAR(dimmed[i] / full[i], 0.3, 1e-6) << i;
    EXPECT_EQ(none[i], 0) << i;
    EXPECT_GT(all[i], full[i]) << i;  // the emitter adds light
  }
}

}  // namespace
}  // namespace relight
