// relight reference --state with the windows' whole state: exterior objects placed for each window
// and frosted glass are traced (reference/reference_portals.h), so probe can be checked against it
// for any state:
//  * a grey wall 2 m outside a south window under a uniform sky takes light from the back of
//    the room; hidden by the state, the room reads as without it; probe agrees with the
//    reference in both (the shell's parallax, which the precompute warns about, is the
//    difference with the wall);
//  * 10° frost under a clear sky with a 30° sun: probe and reference agree sensor by sensor and
//    on the light the floor receives in all.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

std::vector<double> floor_lux(const fs::path& csv) {
  std::vector<double> out;
  const auto rows = parse_csv(read_text(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) out.push_back(std::stod(rows[i].at(8)));
  return out;
}

struct Readings {
  std::vector<double> probe, reference;
};

Readings run_both(const TempDir& dir, const fs::path& scene, const fs::path& rlt,
                  const std::string& state, const std::string& name) {
  const std::string arg = state.empty() ? "" : " --state '" + state + "'";
  const fs::path p = dir.path() / (name + "-probe.csv"), r = dir.path() / (name + "-ref.csv");
  EXPECT_EQ(
      run_relight("probe '" + rlt.string() + "'" + arg + " -o '" + p.string() + "'").exit_code, 0);
  EXPECT_EQ(run_relight("reference '" + scene.string() + "'" + arg +
                        " --spp 16384 --no-progress --sensors-out '" + r.string() + "'")
                .exit_code,
            0);
  return {floor_lux(p), floor_lux(r)};
}

// Mean and worst |probe / reference − 1|, printed.
std::pair<double, double> agreement(const Readings& r, const std::string& name) {
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < r.probe.size(); ++i) {
    const double e = std::abs(r.probe[i] / r.reference[i] - 1);
    sum += e;
    worst = std::max(worst, e);
  }
  const double mean = sum / static_cast<double>(r.probe.size());
  std::printf("%s: probe vs reference mean |Δ| %.2f %%, worst %.2f %%\n", name.c_str(), 100 * mean,
              100 * worst);
  return {mean, worst};
}

nlohmann::json south_window_room() {
  return testing::south_window_room(0.001);
}

TEST(ReferenceState, ExteriorObjectsAreTracedAsTheStatePlacesThem) {
  const TempDir dir;
  nlohmann::json scene = south_window_room();
  scene["materials"]["brick"] = {{"albedo", {0.5, 0.4, 0.3}}};
  scene["exterior"] = {{{"name", "wall"},
                        {"type", "box"},
                        {"min", {-8, 0, 7}},
                        {"max", {12, 4, 7.3}},
                        {"normals", "outward"},
                        {"material", "brick"}}};
  const fs::path file = dir.write("wall.json", scene.dump());
  const fs::path rlt = dir.path() / "wall.rlt";
  ASSERT_EQ(
      run_relight("precompute '" + file.string() + "' -o '" + rlt.string() + "' --no-progress")
          .exit_code,
      0);
  const fs::path hidden = dir.write("hidden.json", R"({"exterior": {"wall": {"visible": false}}})");
  const Readings with = run_both(dir, file, rlt, "", "wall");
  const Readings without = run_both(dir, file, rlt, hidden.string(), "hidden");
  // The back row (z = 1, 3.5 m from the window) sees the sky only above the wall's top.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT(with.reference[i], 0.7 * without.reference[i]) << i;
  }
  const auto [mean, worst] = agreement(with, "exterior wall");
  EXPECT_LT(mean, 0.06);
  EXPECT_LT(worst, 0.12);
  const auto [mean_hidden, worst_hidden] = agreement(without, "wall hidden");
  EXPECT_LT(mean_hidden, 0.02);
  EXPECT_LT(worst_hidden, 0.05);
}

TEST(ReferenceState, FrostedGlassIsTraced) {
  const TempDir dir;
  nlohmann::json scene = south_window_room();
  scene["portals"][0]["environment"] = {{"type", "cie_sky"},
                                        {"sky_type", 12},
                                        {"horizontal_illuminance", 20000},
                                        {"sun", {{"azimuth_deg", 180}, {"altitude_deg", 30}}},
                                        {"sun_illuminance", 60000}};
  const fs::path file = dir.write("sun.json", scene.dump());
  const fs::path rlt = dir.path() / "sun.rlt";
  ASSERT_EQ(
      run_relight("precompute '" + file.string() + "' -o '" + rlt.string() + "' --no-progress")
          .exit_code,
      0);
  const fs::path frost =
      dir.write("frost.json", R"({"portals": {"south window": {"frost_deg": 10}}})");
  const Readings r = run_both(dir, file, rlt, frost.string(), "frost");
  const auto [mean, worst] = agreement(r, "10 degree frost");
  EXPECT_LT(mean, 0.10);
  EXPECT_LT(worst, 0.20);
  double probe = 0, reference = 0;
  for (std::size_t i = 0; i < r.probe.size(); ++i) {
    probe += r.probe[i];
    reference += r.reference[i];
  }
  std::printf("10 degree frost: floor sum probe %.0f lx, reference %.0f lx\n", probe, reference);
  EXPECT_NEAR(probe / reference, 1, 0.03);
}

}  // namespace
}  // namespace relight
