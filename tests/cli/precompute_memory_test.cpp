// The precompute's predicted peak memory (sources/precompute_memory.h) against the peak it then
// measures, on rooms of several sizes and kinds of light; `relight info` prints the same
// prediction; a limit below it (--memory-limit, RELIGHT_MEMORY_LIMIT) refuses the scene before the
// gather operator is traced, exit 2, with the numbers and no file.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "cli/demo_room.h"
#include "run_command.h"
#include "support/daylight_room.h"
#include "support/scene_json.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::TempDir;

// The number after `label` in `text` ("…label 123.4 MB"); NaN when absent.
double megabytes_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

// A sanitizer's shadow memory and quarantine are not the precompute's.
bool under_sanitizer() {
  return std::getenv("RELIGHT_SANITIZER") != nullptr;
}

// The demo room (four luminaires and a window, binary16 storage) at `max_edge`.
nlohmann::json demo_room(double max_edge) {
  nlohmann::json scene = demo_room_scene();
  scene["precompute"]["max_edge"] = max_edge;
  scene["precompute"]["tolerance"] = 0.01;  // fewer bounces, the same matrices
  return scene;
}

// A room with two luminaires of sh_order 8 in single precision, a near-field emitter and a
// movable object: every dense matrix at four bytes a value.
nlohmann::json luminaire_room(double max_edge) {
  testing::WindowRoom room;
  room.albedo = 0.6;
  nlohmann::json scene = testing::window_room_json(room);
  scene["portals"] = nlohmann::json::array();
  scene["sensors"] = {{{"name", "floor"},
                       {"grid",
                        {{"corner", {0.5, 0.8, 0.5}},
                         {"u", {3, 0, 0}},
                         {"v", {0, 0, 4}},
                         {"nu", 12},
                         {"nv", 16}}}}};
  nlohmann::json second = testing::panel_luminaire("second");
  second["position"] = {2, 2.9, 1.5};
  scene["luminaires"] = {testing::panel_luminaire("first"), second};
  testing::add_strip_and_cabinet(scene);
  scene["precompute"] = {
      {"max_edge", max_edge}, {"storage", "fp32"}, {"tolerance", 0.01}, {"sh_order", 8}};
  return scene;
}

struct Measured {
  double estimate = 0, peak = 0, info = 0;
};

Measured precompute_measured(const TempDir& dir, const std::string& name,
                             const nlohmann::json& scene) {
  const fs::path file = dir.write(name + ".json", scene.dump());
  const testing::CommandResult info = run_relight("info '" + file.string() + "'");
  EXPECT_EQ(info.exit_code, 0) << info.err;
  const testing::CommandResult r =
      run_relight("precompute '" + file.string() + "' -o '" +
                  (dir.path() / (name + ".rlt")).string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return {megabytes_after(r.out, "memory estimate: "),
          megabytes_after(r.out, "peak resident memory: "),
          megabytes_after(info.out, "memory estimate: ")};
}

TEST(PrecomputeMemory, TheEstimateIsWithin25PercentOfTheMeasuredPeakOnRoomsOfSeveralSizes) {
  if (under_sanitizer()) GTEST_SKIP() << "a sanitizer's own memory is not the precompute's";
  const TempDir dir;
  const struct {
    std::string name, file;
    nlohmann::json scene;
  } cases[] = {{"demo room, max_edge 0.3", "demo-coarse", demo_room(0.3)},
               {"demo room, max_edge 0.15", "demo-fine", demo_room(0.15)},
               {"luminaires and an emitter, max_edge 0.25", "room-coarse", luminaire_room(0.25)},
               {"luminaires and an emitter, max_edge 0.1", "room-fine", luminaire_room(0.1)}};
  for (const auto& c : cases) {
    const Measured m = precompute_measured(dir, c.file, c.scene);
    std::printf("%s: estimate %.0f MB, measured peak %.0f MB (%+.1f %%), info %.0f MB\n",
                c.name.c_str(), m.estimate, m.peak, 100 * (m.estimate / m.peak - 1), m.info);
    EXPECT_NEAR(m.estimate / m.peak, 1, 0.25) << c.name;
    // `relight info` predicts what the precompute then predicts for itself.
    EXPECT_NEAR(m.info / m.estimate, 1, 0.1) << c.name;
  }
}

TEST(PrecomputeMemory, ALimitBelowTheEstimateRefusesTheSceneWithTheNumbersAndExitTwo) {
  const TempDir dir;
  const fs::path file = dir.write("room.json", luminaire_room(0.25).dump());
  const fs::path out = dir.path() / "room.rlt";
  const std::string precompute =
      "precompute '" + file.string() + "' -o '" + out.string() + "' --no-progress";
  for (const auto& [arguments, shell, source] :
       {std::tuple{precompute + " --memory-limit 20", std::string(), "(--memory-limit)"},
        std::tuple{precompute, std::string("export RELIGHT_MEMORY_LIMIT=20"),
                   "(RELIGHT_MEMORY_LIMIT)"}}) {
    const testing::CommandResult r = run_relight(arguments, shell);
    testing::expect_input_error(r, file.string() + ": too large to precompute here: ");
    EXPECT_NE(r.err.find("need an estimated "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("and 20 MB is available " + std::string(source)), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  const testing::CommandResult bad = run_relight(precompute, "export RELIGHT_MEMORY_LIMIT=lots");
  testing::expect_input_error(bad, "RELIGHT_MEMORY_LIMIT: expected a positive number");
  // A limit above the estimate: precomputed.
  const testing::CommandResult fits = run_relight(precompute + " --memory-limit 100000");
  EXPECT_EQ(fits.exit_code, 0) << fits.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST(PrecomputeMemory, InfoPredictsEachRanksShareForRanks) {
  const TempDir dir;
  const fs::path file = dir.write("room.json", luminaire_room(0.25).dump());
  const testing::CommandResult r = run_relight("info '" + file.string() + "' --ranks 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double one = megabytes_after(r.out, "memory estimate: ");
  const std::size_t second = r.out.find("memory estimate: ", r.out.find("memory estimate: ") + 1);
  ASSERT_NE(second, std::string::npos) << r.out;
  const double rank = megabytes_after(r.out.substr(second), "memory estimate: ");
  EXPECT_NE(r.out.find(" a rank of 4\n"), std::string::npos) << r.out;
  // Each rank holds the whole mesh but a quarter of the rows.
  EXPECT_LT(rank, one) << r.out;
  EXPECT_GT(rank, 0.25 * one) << r.out;
}

}  // namespace
}  // namespace relight
