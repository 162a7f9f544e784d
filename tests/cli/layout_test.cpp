// The layout: a lighting state moves a precomputed luminaire, switches one off and adds luminaires
// the scene does not have, with no new precompute (sources/luminaires/luminaire_lighting.h). The
// moved and added ones are exact in direct light and interreflect through the stored gather
// operator, so `probe` of the state agrees with a fresh precompute of that layout (1 % mean, 3 %
// worst: the fresh one's interreflection is the SH series of each distribution, the run time's the
// distribution itself) and with `relight reference --state` (2 % mean, 8 % worst at 4096 paths
// per sensor), which places them as the state does.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "agreement.h"
#include "run_command.h"
#include "support/scene_json.h"

namespace relight::testing {
namespace {

namespace fs = std::filesystem;

// An asymmetric IES LM-63-2002 file (no symmetry: C 0, 90, 180, 270, 360), 1000 lm: a beam
// thrown toward C90 with little toward C270, or with `toward_c0` toward C0 and little toward C180.
std::string asymmetric_ies(bool toward_c0) {
  const char* wide = "400 520 600 420 20\n";
  const char* side = "400 380 300 150 0\n";
  const char* narrow = "400 200 90 30 0\n";
  std::string s =
      "IESNA:LM-63-2002\n[MANUFAC] relight tests\n[LUMCAT] ASYM-1\nTILT=NONE\n"
      "1 1000 1 5 5 1 2 0 0 0\n1 1 18\n"
      "0 22.5 45 67.5 90\n0 90 180 270 360\n";
  if (toward_c0) return s + wide + side + narrow + side + wide;
  return s + side + wide + side + narrow + side;
}

// A 6 × 3 × 4 m grey room with two luminaires under the ceiling ("asym", the file above, and
// "cos", a cosine-power downlight), a work-plane grid and a wall grid.
nlohmann::json two_luminaire_room(const std::string& ies) {
  nlohmann::json d = nlohmann::json::parse(R"({
  "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] }, "floor": { "albedo": [0.3, 0.25, 0.2] } },
  "luminaires": [
    { "name": "asym", "position": [1.5, 2.9, 1.5], "distribution": { "type": "ies", "file": "" } },
    { "name": "cos", "position": [4.5, 2.9, 1.5],
      "distribution": { "type": "cosine_power", "candela": 900, "exponent": 3 } } ],
  "sensors": [
    { "name": "desk", "grid": { "corner": [0.5, 0.8, 0.5], "u": [5, 0, 0], "v": [0, 0, 3],
                                "nu": 6, "nv": 4 } },
    { "name": "wall", "grid": { "corner": [5.99, 1.0, 0.5], "u": [0, 0, 3], "v": [0, 1, 0],
                                "nu": 4, "nv": 2 }, "normal": [-1, 0, 0] } ],
  "precompute": { "max_edge": 0.5, "gather_rays": 128, "sensor_gather_rays": 1024, "sh_order": 8 }
})");
  d["geometry"] = quad_room(6, 3, 4, "floor", "grey", "grey");
  d["luminaires"][0]["distribution"]["file"] = ies;
  return d;
}

// The layout the state below makes: "asym" 1.5 m along x with C0 turned to +z, "cos" off, and
// two luminaires added from other files (the small EULUMDAT downlight, and an asymmetric file
// whose beam leans the other way).
const char* kLayoutState = R"({ "luminaires": {
  "asym": { "position": [3.0, 2.9, 1.5], "c0": [0, 0, 1] },
  "cos": { "on": false },
  "added ldt": { "position": [4.5, 2.9, 3.0], "distribution": { "type": "ldt", "file": "LDT" } },
  "added asym": { "position": [1.5, 2.9, 3.0], "c0": [-1, 0, 0],
                  "distribution": { "type": "ies", "file": "IES" }, "dimmer": 0.8 } } })";

nlohmann::json layout_state(const std::string& ies, const std::string& ldt) {
  nlohmann::json s = nlohmann::json::parse(kLayoutState);
  s["luminaires"]["added ldt"]["distribution"]["file"] = ldt;
  s["luminaires"]["added asym"]["distribution"]["file"] = ies;
  return s;
}

// The same layout written as a scene, for a fresh precompute.
nlohmann::json layout_scene(const std::string& ies, const std::string& other_ies,
                            const std::string& ldt) {
  nlohmann::json d = two_luminaire_room(ies);
  d["luminaires"][0]["position"] = {3.0, 2.9, 1.5};
  d["luminaires"][0]["c0"] = {0, 0, 1};
  d["luminaires"][1]["dimmer"] = 0;
  d["luminaires"].push_back({{"name", "added ldt"},
                             {"position", {4.5, 2.9, 3.0}},
                             {"distribution", {{"type", "ldt"}, {"file", ldt}}}});
  d["luminaires"].push_back({{"name", "added asym"},
                             {"position", {1.5, 2.9, 3.0}},
                             {"c0", {-1, 0, 0}},
                             {"dimmer", 0.8},
                             {"distribution", {{"type", "ies"}, {"file", other_ies}}}});
  return d;
}

struct LayoutRoom {
  TempDir dir;
  std::string ies, other_ies, ldt;
  fs::path rlt, state;
  LayoutRoom() {
    ies = dir.write("asym.ies", asymmetric_ies(false)).string();
    other_ies = dir.write("asym-c0.ies", asymmetric_ies(true)).string();
    ldt = std::string(RELIGHT_TEST_DATA) + "/photometry/small_axial.ldt";
    rlt = precompute_scene(dir, "room", two_luminaire_room(ies).dump());
    state = dir.write("layout.json", layout_state(other_ies, ldt).dump());
  }
};

TEST(Layout, MovedAndAddedLuminairesMatchAFreshPrecomputeWithinOnePercentMean) {
  LayoutRoom room;
  const fs::path fresh =
      precompute_scene(room.dir, "fresh", layout_scene(room.ies, room.other_ies, room.ldt).dump());
  const fs::path live_csv = room.dir.path() / "live.csv", fresh_csv = room.dir.path() / "fresh.csv";
  auto r = run_relight("probe '" + room.rlt.string() + "' --state '" + room.state.string() +
                       "' -o '" + live_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("probe '" + fresh.string() + "' -o '" + fresh_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Agreement a = relative_agreement(sensor_lux(live_csv), sensor_lux(fresh_csv));
  std::cout << "layout vs fresh precompute: mean " << a.mean << ", worst " << a.worst << "\n";
  EXPECT_LT(a.mean, 0.01);
  EXPECT_LT(a.worst, 0.03);
  // The layout changed the light: the room as precomputed differs by far more.
  const fs::path before_csv = room.dir.path() / "before.csv";
  r = run_relight("probe '" + room.rlt.string() + "' -o '" + before_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(relative_agreement(sensor_lux(before_csv), sensor_lux(fresh_csv)).mean, 0.1);
}

TEST(Layout, MovedAndAddedLuminairesMatchTheReferenceWithinTwoPercentMean) {
  LayoutRoom room;
  const fs::path scene = room.dir.path() / "room.json";
  const fs::path live_csv = room.dir.path() / "live.csv", ref_csv = room.dir.path() / "ref.csv";
  auto r = run_relight("probe '" + room.rlt.string() + "' --state '" + room.state.string() +
                       "' -o '" + live_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene.string() + "' --state '" + room.state.string() +
                  "' --spp 4096 --sensors-out '" + ref_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Agreement a = relative_agreement(sensor_lux(live_csv), sensor_lux(ref_csv));
  std::cout << "layout vs reference: mean " << a.mean << ", worst " << a.worst << "\n";
  EXPECT_LT(a.mean, 0.02);
  EXPECT_LT(a.worst, 0.08);
}

// The reference places the state's layout exactly as the scene would: same seed, same paths.
TEST(Layout, ReferenceOfAStateEqualsReferenceOfTheSceneWithThatLayout) {
  LayoutRoom room;
  const fs::path scene = room.dir.path() / "room.json";
  const fs::path fresh =
      room.dir.write("fresh.json", layout_scene(room.ies, room.other_ies, room.ldt).dump());
  const fs::path a_csv = room.dir.path() / "a.csv", b_csv = room.dir.path() / "b.csv";
  auto r = run_relight("reference '" + scene.string() + "' --state '" + room.state.string() +
                       "' --spp 64 --sensors-out '" + a_csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + fresh.string() + "' --spp 64 --sensors-out '" + b_csv.string() +
                  "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(a_csv), read_text(b_csv));
}

TEST(Layout, ALuminaireOutsideTheSceneIsRefusedWithItsPath) {
  LayoutRoom room;
  const fs::path state = room.dir.write(
      "out.json", R"({ "luminaires": { "asym": { "position": [3.0, 3.5, 1.5] } } })");
  expect_input_error(
      run_relight("probe '" + room.rlt.string() + "' --state '" + state.string() + "'"),
      state.string() + ":luminaires.asym.position: outside the scene");
}

TEST(Layout, AnAddedLuminaireNeedsAPositionAndADistribution) {
  LayoutRoom room;
  const fs::path no_position =
      room.dir.write("a.json", R"({ "luminaires": { "new": { "distribution": { "type": "isotropic",
                                                                "candela": 100 } } } })");
  expect_input_error(
      run_relight("probe '" + room.rlt.string() + "' --state '" + no_position.string() + "'"),
      no_position.string() +
          ":/luminaires/new: no luminaire named \"new\" in the precomputed scene: a luminaire "
          "the state adds needs \"position\"");
  const fs::path no_distribution =
      room.dir.write("b.json", R"({ "luminaires": { "new": { "position": [1, 2, 1] } } })");
  expect_input_error(
      run_relight("probe '" + room.rlt.string() + "' --state '" + no_distribution.string() + "'"),
      no_distribution.string() +
          ":/luminaires/new: no luminaire named \"new\" in the precomputed scene: a luminaire "
          "the state adds needs \"distribution\"");
}

// The report's luminaire schedule is the layout: the moved one where it hangs, the added ones.
TEST(Layout, TheReportListsTheLayoutAsTheStateSetsIt) {
  LayoutRoom room;
  const fs::path html = room.dir.path() / "report.html";
  const auto r = run_relight("report '" + room.rlt.string() + "' --state '" + room.state.string() +
                             "' -o '" + html.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_text(html);
  EXPECT_NE(page.find("<td>asym</td><td>3.00, 2.90, 1.50</td>"), std::string::npos);
  EXPECT_NE(page.find("<td>added ldt</td><td>4.50, 2.90, 3.00</td>"), std::string::npos);
  EXPECT_NE(page.find("<td>added asym</td>"), std::string::npos);
  // The EULUMDAT file's 10 W.
  EXPECT_NE(page.find("<td>small_axial.ldt</td><td>"), std::string::npos);
  EXPECT_NE(page.find("</td><td>10.0</td>"), std::string::npos);
}

// Inverse design over the layout: the added luminaires are free dimmers with the scene's, and
// the state it writes meets the target when probed.
TEST(Layout, OptimizeDimsTheAddedLuminairesToo) {
  LayoutRoom room;
  const fs::path targets =
      room.dir.write("targets.json", R"({ "sensors": { "desk": { "em_min": 150 } } })");
  const fs::path out = room.dir.path() / "designed.json";
  auto r = run_relight("optimize '" + room.rlt.string() + "' --targets '" + targets.string() +
                       "' --state '" + room.state.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json designed = nlohmann::json::parse(read_text(out));
  ASSERT_TRUE(designed["luminaires"]["added ldt"].contains("dimmer")) << designed.dump();
  ASSERT_TRUE(designed["luminaires"]["added asym"].contains("dimmer")) << designed.dump();
  const fs::path csv = room.dir.path() / "designed.csv";
  r = run_relight("probe '" + room.rlt.string() + "' --state '" + out.string() + "' -o '" +
                  csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> lux = sensor_lux(csv);
  double desk = 0;
  for (std::size_t i = 0; i < 24; ++i) desk += lux[i] / 24;  // the 6 × 4 desk grid comes first
  EXPECT_GT(desk, 150 * 0.995);
  EXPECT_LT(desk, 150 * 1.05);  // the least power: no more light than the target needs
}

// "runtime_bounce": false leaves the gather operator out: the file is smaller and refuses a move.
TEST(Layout, WithoutTheGatherOperatorAMoveIsRefused) {
  LayoutRoom room;
  nlohmann::json lean = two_luminaire_room(room.ies);
  lean["precompute"]["runtime_bounce"] = false;
  const fs::path rlt = precompute_scene(room.dir, "lean", lean.dump());
  EXPECT_LT(fs::file_size(rlt), fs::file_size(room.rlt));
  expect_input_error(
      run_relight("probe '" + rlt.string() + "' --state '" + room.state.string() + "'"),
      "luminaires: moving or adding a luminaire needs the gather operator");
  EXPECT_EQ(run_relight("probe '" + rlt.string() + "'").exit_code, 0);
  // A scene whose windows bounce the sun at run time cannot leave it out.
  nlohmann::json window = lean;
  window["materials"]["glass"] = {{"albedo", {0, 0, 0}}, {"portal", true}};
  window["geometry"].push_back({{"type", "quad"},
                                {"corner", {2, 1, 3.99}},
                                {"u", {1, 0, 0}},
                                {"v", {0, 1, 0}},
                                {"material", "glass"}});
  window["portals"] = {{{"name", "w"},
                        {"material", "glass"},
                        {"environment", {{"type", "uniform"}, {"luminance", 1000}}}}};
  const fs::path scene = room.dir.write("window.json", window.dump());
  expect_input_error(run_relight("info '" + scene.string() + "'"),
                     scene.string() + ":/precompute/runtime_bounce: portals, emitters");
}

// `relight bench --layout`: both frames timed, the moved and the added luminaire lit at run time.
TEST(Layout, BenchLayoutPrintsFirstAndConvergedFrames) {
  LayoutRoom room;
  const auto r = run_relight("bench '" + room.rlt.string() + "' --layout --frames 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "layout");
  EXPECT_EQ(j["luminaires_live"], 2);
  EXPECT_EQ(j["luminaires"], 3);
  EXPECT_GT(j["first_frame_ms"].get<double>(), 0);
  EXPECT_GE(j["converged_ms"].get<double>(), j["first_frame_ms"].get<double>());
  EXPECT_GT(j["bounce_ms"].get<double>(), 0);
  EXPECT_GT(j["receivers"].get<int>(), 0);
  expect_input_error(run_relight("bench '" + room.rlt.string() + "' --layout --aim --frames 1"),
                     room.rlt.string() + ": --layout moves and adds luminaires alone");
}

// `relight bench --edits`: one line per edit the room allows (two luminaires of different
// distributions, no window, object or emitter), first and converged frames as the studio shows
// them: a dimmer's first frame is its converged one; a moved luminaire's and a repainted wall's
// first frames differ from the converged ones by less than the 10% a first frame may.
TEST(Layout, BenchEditsTimesEveryEditTheRoomAllows) {
  LayoutRoom room;
  const auto r = run_relight("bench '" + room.rlt.string() + "' --edits --frames 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, nlohmann::json> edits;
  nlohmann::json summary;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j.contains("edit")) {
      edits[j["edit"]] = j;
    } else {
      summary = j;
    }
  }
  const std::vector<std::string> expected = {"aim",
                                             "colour_temperature",
                                             "dimmer",
                                             "distribution_swap",
                                             "luminaire_move",
                                             "material_albedo",
                                             "material_roughness"};
  std::vector<std::string> names;
  for (const auto& [name, j] : edits) names.push_back(name);
  EXPECT_EQ(names, expected) << r.out;
  double worst_first = 0;
  for (const auto& [name, j] : edits) {
    EXPECT_EQ(j["frames"], 2) << name;
    EXPECT_GT(j["receivers"].get<int>(), 0) << name;
    EXPECT_GT(j["first_ms"].get<double>(), 0) << name;
    EXPECT_GE(j["converged_ms"].get<double>(), j["first_ms"].get<double>()) << name;
    EXPECT_LT(j["first_error"].get<double>(), 0.1) << name;
    worst_first = std::max(worst_first, j["first_ms"].get<double>());
  }
  EXPECT_EQ(edits["dimmer"]["first_error"], 0.0);
  EXPECT_EQ(edits["dimmer"]["first_ms"], edits["dimmer"]["converged_ms"]);
  EXPECT_GT(edits["luminaire_move"]["first_error"].get<double>(), 0);
  EXPECT_GT(edits["material_albedo"]["first_error"].get<double>(), 0);
  EXPECT_EQ(summary["edits"], expected.size());
  EXPECT_EQ(summary["worst_first_ms"], worst_first);
  expect_input_error(run_relight("bench '" + room.rlt.string() + "' --edits --aim --frames 1"),
                     room.rlt.string() + ": --edits times every kind of edit itself");
}

}  // namespace
}  // namespace relight::testing
