// `relight probe --check`: each task area's maintained Ē, U0 and UGR against its EN 12464-1
// requirements; the maintenance factor scales the electric light (a room lit by one luminaire: Ē by
// MF exactly, U0 unchanged, UGR by 8·log10 MF), a failed requirement still exits 0, an undeclared
// factor is 1 with a warning, and bad task keys exit 2.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::TempDir;

nlohmann::json panel_room() {
  testing::WindowRoom room;
  room.albedo = 0.5;
  nlohmann::json scene = testing::window_room_json(room);
  scene["luminaires"] = {testing::panel_luminaire("panel")};
  scene["sensors"] = {
      {{"name", "desk"},
       {"grid",
        {{"corner", {1, 0.8, 1.5}}, {"u", {2, 0, 0}}, {"v", {0, 0, 3}}, {"nu", 4}, {"nv", 6}}}}};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}};
  return scene;
}

fs::path precompute(const TempDir& dir, const nlohmann::json& scene, const std::string& name) {
  return testing::precompute_scene(dir, name, scene.dump());
}

// The number after `label` on the line of stdout that starts with it.
double value_after(const std::string& out, const std::string& label) {
  const std::size_t at = out.find(label);
  EXPECT_NE(at, std::string::npos) << label << " in " << out;
  return at == std::string::npos ? NAN : std::stod(out.substr(at + label.size()));
}

TEST(ProbeCheck, MaintainedValuesAgainstTheTaskRequirements) {
  const TempDir dir;
  // Initial values first, without a task.
  const fs::path plain = precompute(dir, panel_room(), "plain");
  const auto initial = run_relight("probe '" + plain.string() + "'");
  ASSERT_EQ(initial.exit_code, 0) << initial.err;
  const double e_avg = value_after(initial.out, "Eavg ");
  const double u0 = value_after(initial.out, "U0 ");
  const auto g = run_relight("glare '" + plain.string() + "' --observer 2,1.2,1 --view 0,0,1");
  const double ugr = nlohmann::json::parse(g.out)["ugr"].get<double>();

  nlohmann::json scene = panel_room();
  scene["maintenance_factor"] = 0.8;
  // Ē passes before maintenance and fails after; U0 and UGR pass.
  scene["sensors"][0]["task"] = {{"em", 0.9 * e_avg},
                                 {"u0", 0.5 * u0},
                                 {"ugr_l", 19},
                                 {"observers", {{{"position", {2, 1.2, 1}}, {"view", {0, 0, 1}}}}}};
  const fs::path rlt = precompute(dir, scene, "task");
  const auto r = run_relight("probe '" + rlt.string() + "' --check");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  EXPECT_EQ(r.err, "");  // the factor is declared
  EXPECT_NE(r.out.find("task \"desk\" (maintained values, maintenance factor 0.80)"),
            std::string::npos);
  const std::string check = r.out.substr(r.out.find("task \"desk\""));
  const auto line = [&](const std::string& label) {
    const std::size_t at = check.find("\n" + label);
    return at == std::string::npos ? std::string()
                                   : check.substr(at + 1, check.find('\n', at + 1) - at - 1);
  };
  EXPECT_NEAR(value_after(line("  Em "), "  Em "), 0.8 * e_avg, 1e-3 * e_avg + 0.05);
  EXPECT_NE(line("  Em ").find("FAIL"), std::string::npos) << line("  Em ");
  EXPECT_NEAR(value_after(line("  U0 "), "  U0 "), u0, 1e-3);
  EXPECT_NE(line("  U0 ").find("pass"), std::string::npos) << line("  U0 ");
  EXPECT_NEAR(value_after(line("  UGR "), "  UGR "), ugr + 8 * std::log10(0.8), 0.06);
  EXPECT_NE(line("  UGR ").find("pass"), std::string::npos) << line("  UGR ");
  // Without --check: nothing of it.
  EXPECT_EQ(run_relight("probe '" + rlt.string() + "'").out.find("task"), std::string::npos);

  // Undeclared: 1, with a warning.
  scene.erase("maintenance_factor");
  const fs::path undeclared = precompute(dir, scene, "undeclared");
  const auto w = run_relight("probe '" + undeclared.string() + "' --check");
  EXPECT_EQ(w.exit_code, 0);
  EXPECT_NE(w.err.find("warning: the scene declares no \"maintenance_factor\""), std::string::npos);
  EXPECT_NEAR(value_after(w.out, "  Em "), e_avg, 1e-3 * e_avg + 0.05);
}

TEST(ProbeCheck, BadTaskKeysExitTwoWithTheirJsonPath) {
  const TempDir dir;
  const auto fails = [&](const nlohmann::json& scene, const std::string& expected) {
    const fs::path file = dir.write("bad.json", scene.dump());
    testing::expect_input_error(run_relight("info '" + file.string() + "'"),
                                file.string() + ":" + expected);
  };
  nlohmann::json scene = panel_room();
  scene["maintenance_factor"] = 1.5;
  fails(scene, "/maintenance_factor: a maintenance factor lies in (0, 1]");
  scene = panel_room();
  scene["sensors"][0]["task"] = {{"ugr_l", 19}};
  fails(scene, "/sensors/0/task/ugr_l: a UGR limit needs \"observers\"");
  scene["sensors"][0]["task"] = {{"u0", 1.5}};
  fails(scene, "/sensors/0/task/u0: u0 is a ratio");
  scene["sensors"][0]["task"] = nlohmann::json::object();
  fails(scene, "/sensors/0/task: give at least one of em, u0, ugr_l");
  scene["sensors"][0]["task"] = {{"em", 500}, {"lux", 3}};
  fails(scene, "/sensors/0/task/lux: unknown key");
}

}  // namespace
}  // namespace relight
