// `relight optimize` as a user runs it: the one JSON line, the state it writes loaded as it is by
// `probe` (the achieved values reproduced from its CSV), `reference` (the desk's Em within 3 %) and
// `render`, infeasible targets (exit 0, the binding one named), bad targets (exit 2 with the JSON
// path), and a start state's relative photometry file still found from the output's folder.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/design_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::TempDir;

const TempDir& room_dir() {
  static const TempDir dir;
  return dir;
}

const fs::path& room_rlt() {
  static const fs::path rlt =
      testing::precompute_scene(room_dir(), "office", testing::design_room_json().dump());
  return rlt;
}

// The path quoted for the shell.
std::string q(const fs::path& p) {
  std::string quoted = p.string();
  quoted.insert(quoted.begin(), '\'');
  quoted.push_back('\'');
  return quoted;
}

// Per set name: its points' lux from a probe CSV.
std::map<std::string, std::vector<double>> csv_lux(const fs::path& csv) {
  std::map<std::string, std::vector<double>> out;
  const auto rows = testing::parse_csv(testing::read_text(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) out[rows[i][0]].push_back(std::stod(rows[i][8]));
  return out;
}

nlohmann::json optimize(const std::string& targets, const fs::path& out,
                        const std::string& extra = "") {
  const fs::path file = room_dir().write("targets.json", targets);
  const testing::CommandResult r = run_relight("optimize " + q(room_rlt()) + " --targets " +
                                               q(file) + " -o " + q(out) + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  return nlohmann::json::parse(r.out);
}

TEST(OptimizeCommand, TheStateItWritesReproducesTheAchievedValuesInProbe) {
  const fs::path state = room_dir().path() / "designed.json";
  const nlohmann::json line = optimize(
      R"({"sensors": {"desk": {"em_min": 60, "u0_min": 0.4}, "wall": {"e_min": 20}},
          "power_w": {"left": 30, "right": 40}})",
      state);
  ASSERT_EQ(line["feasible"], true) << line.dump();
  for (const char* key : {"objective", "iterations", "seconds", "binding", "targets"}) {
    EXPECT_TRUE(line.contains(key)) << key;
  }
  EXPECT_EQ(line["watts_from_data"], true);  // "middle" from its IES file
  const fs::path csv = room_dir().path() / "designed.csv";
  const testing::CommandResult probe =
      run_relight("probe " + q(room_rlt()) + " --state " + q(state) + " -o " + q(csv));
  ASSERT_EQ(probe.exit_code, 0) << probe.err;
  const auto lux = csv_lux(csv);
  for (const nlohmann::json& t : line["targets"]) {
    const std::vector<double>& set = lux.at(t["set"].get<std::string>());
    double sum = 0, lo = 1e300;
    for (const double v : set) {
      sum += v;
      lo = std::min(lo, v);
    }
    const double mean = sum / static_cast<double>(set.size());
    const std::string kind = t["target"];
    const double probed = kind == "em_min" ? mean : kind == "u0_min" ? lo / mean : lo;
    const double achieved = t["achieved"];
    EXPECT_NEAR(probed, achieved, 1e-6 * achieved) << kind;
    EXPECT_GE(achieved, t["value"].get<double>()) << kind;
    EXPECT_EQ(t["met"], true);
  }
  // The reference path tracer on the scene and the same state: the desk's Em within 3 %.
  const fs::path reference_csv = room_dir().path() / "reference.csv";
  const testing::CommandResult reference =
      run_relight("reference " + q(room_dir().path() / "office.json") + " --state " + q(state) +
                  " --spp 256 --sensors-out " + q(reference_csv));
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  const std::vector<double> desk = csv_lux(reference_csv).at("desk");
  double traced = 0;
  for (const double v : desk) traced += v / static_cast<double>(desk.size());
  EXPECT_NEAR(traced, line["targets"][0]["achieved"].get<double>(), 0.03 * traced);
  const testing::CommandResult render =
      run_relight("render " + q(room_rlt()) + " --state " + q(state) +
                  " --width 32 --height 24 -o " + q(room_dir().path() / "designed.png"));
  EXPECT_EQ(render.exit_code, 0) << render.err;
}

// `relight bench --optimize`: the optimisation timed against a relight, one JSON line.
TEST(OptimizeCommand, BenchTimesItAgainstARelight) {
  const fs::path targets =
      room_dir().write("bench.json", R"({"sensors": {"desk": {"em_min": 50}}})");
  const testing::CommandResult r =
      run_relight("bench " + q(room_rlt()) + " --frames 3 --optimize " + q(targets));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json line = nlohmann::json::parse(r.out);
  EXPECT_EQ(line["mode"], "optimize");
  EXPECT_EQ(line["feasible"], true);
  EXPECT_GT(line["median_ms"].get<double>(), 0);
  EXPECT_NEAR(line["ratio_to_relight"].get<double>(),
              line["median_ms"].get<double>() / line["relight_ms"].get<double>(), 1e-9);
}

TEST(OptimizeCommand, InfeasibleTargetsExitZeroNamingTheBindingOne) {
  const nlohmann::json line =
      optimize(R"({"sensors": {"wall": {"em_min": 100000}}})", room_dir().path() / "closest.json");
  EXPECT_EQ(line["feasible"], false);
  EXPECT_EQ(line["binding"][0], "wall: em_min");
  EXPECT_EQ(line["targets"][0]["met"], false);
  EXPECT_TRUE(fs::exists(room_dir().path() / "closest.json"));
}

TEST(OptimizeCommand, BadTargetsExitTwoWithTheirJsonPath) {
  const fs::path file = room_dir().write("bad.json", R"({"sensors": {"hall": {"em_min": 300}}})");
  const fs::path out = room_dir().path() / "never.json";
  testing::expect_input_error(
      run_relight("optimize " + q(room_rlt()) + " --targets " + q(file) + " -o " + q(out)),
      file.string() + ":/sensors/hall: no sensor set named \"hall\"");
  const fs::path minmax =
      room_dir().write("minmax.json", R"({"sensors": {"desk": {"e_min": 300, "e_max": 100}}})");
  testing::expect_input_error(
      run_relight("optimize " + q(room_rlt()) + " --targets " + q(minmax) + " -o " + q(out)),
      minmax.string() + ":/sensors/desk/e_min: is above e_max");
  EXPECT_FALSE(fs::exists(out));
}

// A start state in its own folder with a relative IES file; the result written elsewhere still
// loads (the path rebased onto the output's folder), with the start's distribution kept.
TEST(OptimizeCommand, AStartStatesRelativeFilesStillLoadFromTheOutputFolder) {
  const fs::path states = room_dir().path() / "states", out = room_dir().path() / "out";
  fs::create_directories(states / "ies");
  fs::create_directories(out);
  fs::copy_file(fs::path(RELIGHT_TEST_DATA) / "photometry/bilateral_90_270_2019.ies",
                states / "ies/b.ies", fs::copy_options::overwrite_existing);
  {
    std::ofstream(states / "start.json")
        << R"({"luminaires": {"left": {"distribution": {"type": "ies", "file": "ies/b.ies"}}}})";
  }
  const fs::path targets = room_dir().write("t.json", R"({"sensors": {"desk": {"em_min": 40}}})");
  const testing::CommandResult r =
      run_relight("optimize " + q(room_rlt()) + " --targets " + q(targets) + " --state " +
                  q(states / "start.json") + " -o " + q(out / "result.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(testing::read_text(out / "result.json"));
  EXPECT_EQ(doc["luminaires"]["left"]["distribution"]["file"], "../states/ies/b.ies");
  EXPECT_EQ(run_relight("probe " + q(room_rlt()) + " --state " + q(out / "result.json")).exit_code,
            0);
}

}  // namespace
}  // namespace relight
