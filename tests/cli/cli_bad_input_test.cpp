// The exit-code contract: bad input or arguments exit 2 with exactly one line
// "error: FILE[:LINE|JSON-PATH]: reason" on stderr, never a crash.
#include <algorithm>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "math/vec3.h"
#include "run_command.h"

namespace relight {
namespace {

using testing::expect_input_error;
using testing::run_relight;
using testing::TempDir;

const char* kRoom = R"({
  "materials": { "white": { "albedo": [0.7, 0.7, 0.7] } },
  "geometry": [ { "type": "box", "min": [0,0,0], "max": [3,2.5,3], "normals": "inward",
                  "material": "white" } ],
  "luminaires": [ { "name": "down", "position": [1.5, 2.4, 1.5],
                    "distribution": { "type": "DIST" } } ],
  "sensors": [ { "name": "floor", "points": [[1.5, 0, 1.5]] } ]
})";

std::string room_with(const std::string& distribution) {
  std::string s = kRoom;
  s.replace(s.find("\"type\": \"DIST\""), 14, distribution);
  return s;
}

// A top-level environment: a bad one gets its JSON path; `relight reference` lights a good one
// (here an open floor under a uniform sky: an up-facing sensor reads π L), and `relight
// precompute`, which does not carry it yet, refuses the scene rather than drop it.
TEST(CliBadInput, TopLevelEnvironment) {
  TempDir dir;
  const std::string floor = R"({
  "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
  "geometry": [ { "type": "quad", "corner": [-50, 0, -50], "u": [0, 0, 100], "v": [100, 0, 0],
                  "material": "grey" } ],
  "sensors": [ { "name": "up", "points": [[0, 0, 0]] } ],
  "environment": ENV
})";
  const auto with = [&](const std::string& env) {
    std::string s = floor;
    return s.replace(s.find("ENV"), 3, env);
  };
  const auto bad = dir.write("bad.json", with(R"({ "type": "uniform", "luminance": "bright" })"));
  expect_input_error(run_relight("info '" + bad.string() + "'"),
                     bad.string() + ":/environment/luminance:");
  const auto good = dir.write("good.json", with(R"({ "type": "uniform", "luminance": 1000 })"));
  const auto csv = dir.path() / "e.csv";
  const testing::CommandResult r =
      run_relight("reference '" + good.string() + "' --spp 4096 --max-bounces 1 --sensors-out '" +
                  csv.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> lux = testing::sensor_lux(csv);
  ASSERT_EQ(lux.size(), 1u);
  EXPECT_NEAR(lux[0], 1000 * kPi, 0.02 * 1000 * kPi);
  // The visibility cuts' settings.
  nlohmann::json doc = nlohmann::json::parse(with(R"({ "type": "uniform", "luminance": 1000 })"));
  doc["precompute"] = {{"cuts", {{"directions", 1000}}}};
  const auto odd = dir.write("odd.json", doc.dump());
  expect_input_error(
      run_relight("precompute '" + odd.string() + "' -o '" + (dir.path() / "x.rlt").string() +
                  "' --no-progress"),
      odd.string() + ":/precompute/cuts/directions: directions must be a power of two");

  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.rlt"));
}

TEST(CliBadInput, MalformedJson) {
  TempDir dir;
  const auto scene =
      dir.write("s.json", "{ \"materials\": {\n  \"white\": { \"albedo\": [1,1,] }\n}\n");
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     scene.string() + ":2: malformed JSON");
}

TEST(CliBadInput, UnknownKey) {
  TempDir dir;
  std::string text = room_with(R"("type": "isotropic", "candela": 10, "lumens": 3)");
  const auto scene = dir.write("s.json", text);
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     scene.string() + ":/luminaires/0/distribution/lumens: unknown key");
}

TEST(CliBadInput, MissingSceneFile) {
  TempDir dir;
  const auto scene = dir.path() / "absent.json";
  expect_input_error(run_relight("reference '" + scene.string() + "'"),
                     scene.string() + ": cannot open");
}

TEST(CliBadInput, MissingPhotometryFile) {
  TempDir dir;
  const auto scene = dir.write("s.json", room_with(R"("type": "ies", "file": "nowhere.ies")"));
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     scene.string() + ":/luminaires/0/distribution/file: file not found");
}

TEST(CliBadInput, NegativeSize) {
  TempDir dir;
  std::string text = room_with(R"("type": "isotropic", "candela": 10)");
  text.replace(text.find("\"max\": [3,2.5,3]"), 16, "\"max\": [-3,2.5,3]");
  const auto scene = dir.write("s.json", text);
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     scene.string() + ":/geometry/0/max: box max must exceed min");
}

TEST(CliBadInput, NotANumber) {
  TempDir dir;
  // JSON has no NaN literal: a NaN written as such is malformed JSON, and so is a
  // literal that overflows a double.
  const auto nan_scene = dir.write("nan.json", room_with(R"("type": "isotropic", "candela": NaN)"));
  expect_input_error(run_relight("info '" + nan_scene.string() + "'"),
                     nan_scene.string() + ":6: malformed JSON");
  const auto inf_scene =
      dir.write("inf.json", room_with(R"("type": "isotropic", "candela": 1e999)"));
  expect_input_error(run_relight("info '" + inf_scene.string() + "'"),
                     inf_scene.string() + ":6: malformed JSON: number out of range");
}

TEST(CliBadInput, TruncatedIes) {
  TempDir dir;
  dir.write("cut.ies",
            "IESNA:LM-63-2002\n[TEST] truncated\nTILT=NONE\n1 1000 1 5 1 1 2 0 0 0\n1 1 10\n"
            "0 22.5 45\n");
  const auto scene = dir.write("s.json", room_with(R"("type": "ies", "file": "cut.ies")"));
  const auto r = run_relight("info '" + scene.string() + "'");
  expect_input_error(r, (dir.path() / "cut.ies").string() + ":");
}

TEST(CliBadInput, TruncatedLdt) {
  TempDir dir;
  dir.write("cut.ldt", "Maker\n1\n1\n1\n0\n19\n5\nreport\nname\n");
  const auto scene = dir.write("s.json", room_with(R"("type": "ldt", "file": "cut.ldt")"));
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     (dir.path() / "cut.ldt").string() + ":");
}

TEST(CliBadInput, InfoOfATruncatedPhotometricFileNamesItsLine) {
  TempDir dir;
  const auto ies = dir.write("cut.ies", "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 5 1 1 2 0 0 0\n");
  expect_input_error(run_relight("info '" + ies.string() + "'"), ies.string() + ":");
  const auto ldt = dir.write("cut.LDT", "Maker\n1\n1\n1\n0\n19\n5\nreport\nname\n");
  expect_input_error(run_relight("info '" + ldt.string() + "'"), ldt.string() + ":");
}

// `relight info FILE.ldt`: one JSON line with the summary's keys (their values are pinned by
// tests/light/photometry_summary_test.cpp).
TEST(CliInfo, APhotometricFileGivesOneJsonLine) {
  const std::string file = std::string(RELIGHT_TEST_DATA) + "/photometry/small_axial.ldt";
  const auto r = run_relight("info '" + file + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["catalogue"], "RL-1");
  EXPECT_NEAR(j["max_cd"].get<double>(), 300.0, 1e-9);
  EXPECT_EQ(j["watts"].get<double>(), 10.0);
  EXPECT_EQ(j["symmetry"], "axial");
  EXPECT_TRUE(j["opening_m"].is_object());
}

TEST(CliBadInput, BrokenObj) {
  TempDir dir;
  dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  std::string text = room_with(R"("type": "isotropic", "candela": 10)");
  text.replace(text.find("\"geometry\": ["), 13,
               R"("geometry": [ { "type": "mesh", "file": "broken.obj", "material": "white" },)");
  const auto scene = dir.write("s.json", text);
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     (dir.path() / "broken.obj").string() + ":4:");
}

TEST(CliBadInput, BadArguments) {
  TempDir dir;
  const auto scene = dir.write("s.json", room_with(R"("type": "isotropic", "candela": 10)"));
  const auto r = run_relight("reference '" + scene.string() + "' --spp 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("error: relight reference: --spp", 0), 0u) << r.err;
  const auto unknown_camera = run_relight("reference '" + scene.string() + "' --camera nope -o " +
                                          (dir.path() / "x.png").string());
  expect_input_error(unknown_camera, "--camera: scene has no camera named \"nope\"");
  EXPECT_EQ(run_relight("frobnicate").exit_code, 2);
}

TEST(CliHelp, EverySubcommandHasHelp) {
  for (const char* sub : {"reference", "info", "demo"}) {
    const auto r = run_relight(std::string(sub) + " --help");
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub << ": " << r.out;
  }
}

}  // namespace
}  // namespace relight
