// `relight analyze SCENE.rlt --sh-energy` as a user runs it, on a small precomputed room
// with a skylight and a south window (tests/support/daylight_room.h) and coloured walls:
// per portal, order and channel the CSV's energies are non-negative, the shares of each
// portal and channel sum to 1 and the cumulative share climbs to 1; the table names both
// portals. Without --sh-energy, or on a file without portals: bad input (exit 2, one line).
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::expect_input_error;
using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

constexpr int kPortalShOrder = 4;

std::string quoted(const fs::path& p) {
  std::string q = "'";  // appended piecewise: "'" + p.string() trips GCC 12's -Wrestrict
  q += p.string();
  q += '\'';
  return q;
}

class AnalyzeCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    testing::WindowRoom room;
    room.skylight = testing::Rect{1.5, 2.5, 2, 3};
    room.south_window = testing::Rect{1, 3, 0.9, 2.1};
    nlohmann::json scene = testing::window_room_json(room);
    scene["materials"]["room"]["albedo"] = {0.7, 0.5, 0.3};
    scene["sensors"] = {
        {{"name", "floor"}, {"points", {{2, 0, 2}, {2, 0, 4}}}, {"normal", {0, 1, 0}}}};
    scene["precompute"] = {{"max_edge", 0.6},
                           {"gather_rays", 32},
                           {"sensor_gather_rays", 64},
                           {"portal_sh_order", kPortalShOrder},
                           {"portal_face_size", 8}};
    rlt_ = dir_->path() / "window.rlt";
    precompute_ = std::make_unique<CommandResult>(
        run_relight("precompute " + quoted(dir_->write("window.json", scene.dump())) + " -o " +
                    quoted(rlt_) + " --no-progress"));
  }
  static void TearDownTestSuite() {
    precompute_.reset();
    dir_.reset();
  }
  void SetUp() override { ASSERT_EQ(precompute_->exit_code, 0) << precompute_->err; }

  static std::unique_ptr<TempDir> dir_;
  static fs::path rlt_;
  static std::unique_ptr<CommandResult> precompute_;
};

std::unique_ptr<TempDir> AnalyzeCommand::dir_;
fs::path AnalyzeCommand::rlt_;
std::unique_ptr<CommandResult> AnalyzeCommand::precompute_;

struct Row {
  int l = 0;
  double energy = 0, share = 0, cumulative = 0;
};

TEST_F(AnalyzeCommand, ShEnergyCsvSharesSumToOne) {
  const fs::path csv = dir_->path() / "energy.csv";
  const CommandResult r = run_relight("analyze " + quoted(rlt_) + " --sh-energy -o " + quoted(csv));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("portal \"skylight\": indirect SH transfer"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("portal \"south window\": indirect SH transfer"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("wrote " + csv.string()), std::string::npos) << r.out;

  const auto cells = parse_csv(read_text(csv));
  ASSERT_FALSE(cells.empty());
  EXPECT_EQ(cells[0], (std::vector<std::string>{"portal", "l", "channel", "energy", "share",
                                                "cumulative", "shell_energy"}));
  ASSERT_EQ(cells.size(), 1u + 2 * kPortalShOrder * 3);
  std::map<std::pair<std::string, std::string>, std::vector<Row>> series;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    ASSERT_EQ(cells[i].size(), 7u) << "row " << i;
    // Both windows show a uniform 1000 cd/m² sky: the outward half's c_00 is
    // 1000 · Y_00 · 2π = 1772.5 cd/m², its energy c_00² (the cubemap's quadrature within 2 %).
    if (cells[i][1] == "0") {
      EXPECT_NEAR(std::stod(cells[i][6]), 1772.5 * 1772.5, 0.02 * 3.14e6) << "row " << i;
    }
    series[{cells[i][0], cells[i][2]}].push_back({std::stoi(cells[i][1]), std::stod(cells[i][3]),
                                                  std::stod(cells[i][4]), std::stod(cells[i][5])});
  }
  ASSERT_EQ(series.size(), 6u);  // two portals × r, g, b
  for (const auto& [key, rows] : series) {
    const std::string what = key.first + " " + key.second;
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(kPortalShOrder)) << what;
    double shares = 0, previous = 0;
    for (std::size_t l = 0; l < rows.size(); ++l) {
      EXPECT_EQ(rows[l].l, static_cast<int>(l)) << what;
      EXPECT_GE(rows[l].energy, 0) << what << " l " << l;
      EXPECT_GE(rows[l].share, 0) << what << " l " << l;
      shares += rows[l].share;
      EXPECT_NEAR(rows[l].cumulative, shares, 1e-7) << what << " l " << l;
      EXPECT_GE(rows[l].cumulative, previous) << what << " l " << l;
      previous = rows[l].cumulative;
    }
    EXPECT_NEAR(shares, 1.0, 1e-7) << what;
    EXPECT_NEAR(rows.back().cumulative, 1.0, 1e-9) << what;
    EXPECT_GT(rows[0].energy, 0) << what;  // light comes in through every window
  }
  // Albedo 0.7, 0.5, 0.3: the interreflected uniform (l = 0) response orders r > g > b.
  for (const std::string portal : {"skylight", "south window"}) {
    const double r0 = series[{portal, "r"}][0].energy, g0 = series[{portal, "g"}][0].energy,
                 b0 = series[{portal, "b"}][0].energy;
    EXPECT_GT(r0, g0) << portal;
    EXPECT_GT(g0, b0) << portal;
  }
}

TEST_F(AnalyzeCommand, TableWithoutCsv) {
  const CommandResult r = run_relight("analyze " + quoted(rlt_) + " --sh-energy");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("share R"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("100.00%"), std::string::npos) << r.out;  // cumulative at the last l
}

TEST_F(AnalyzeCommand, MissingAnalysisIsAUsageError) {
  expect_input_error(run_relight("analyze " + quoted(rlt_)), "relight analyze: ");
}

TEST(AnalyzeCommandErrors, FileWithoutPortals) {
  TempDir dir;
  const char* room = R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [2, 2, 2], "normals": "inward",
                    "material": "grey" } ],
    "luminaires": [ { "name": "bulb", "position": [1, 1.5, 1],
                      "distribution": { "type": "isotropic", "candela": 10 } } ],
    "precompute": { "max_edge": 1, "gather_rays": 8, "sh_order": 2 }
  })";
  const fs::path rlt = dir.path() / "box.rlt";
  const CommandResult pre = run_relight("precompute " + quoted(dir.write("box.json", room)) +
                                        " -o " + quoted(rlt) + " --no-progress");
  ASSERT_EQ(pre.exit_code, 0) << pre.err;
  const CommandResult r = run_relight("analyze " + quoted(rlt) + " --sh-energy");
  expect_input_error(r, rlt.string() + ": the scene has no portals");
  EXPECT_NE(r.err.find("--sh-energy analyses portal transfer"), std::string::npos) << r.err;
}

TEST(AnalyzeCommandErrors, MissingFile) {
  TempDir dir;
  const fs::path missing = dir.path() / "missing.rlt";
  expect_input_error(run_relight("analyze " + quoted(missing) + " --sh-energy"),
                     missing.string() + ": ");
}

}  // namespace
}  // namespace relight
