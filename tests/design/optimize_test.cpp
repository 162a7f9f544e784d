// Inverse design end to end (design/optimize.h) on the design room: the document written, the
// binding target named, daylight-linked dimming, fixed luminaires, and aims within a cone
// against a grid search over aims.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "design/aim_search.h"
#include "design/dimmer_program.h"
#include "design/illuminance_model.h"
#include "design/optimize.h"
#include "design_room_fixture.h"
#include "light/luminaire_frame.h"

namespace relight {
namespace {

using testing::design_room;

DesignTargets targets_of(const Scene& scene, const std::string& json) {
  return parse_design_targets(nlohmann::json::parse(json), scene, "targets");
}

// The desk's mean with every luminaire at full output and dark windows.
double full_desk_mean(RelitScene& relit) {
  const auto lux = testing::readings(relit, {{"portals", {{"south", {{"tint", {0, 0, 0}}}}}}});
  return set_value(lux[0], TargetKind::kEmMin);
}

TEST(Optimize, TheWrittenStateReproducesTheAchievedValuesAndDarkensTheWindows) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const double target = 0.5 * full_desk_mean(relit);
  const DesignTargets targets = targets_of(
      relit.scene(), R"({"sensors": {"desk": {"em_min": )" + std::to_string(target) +
                         R"(, "u0_min": 0.3}}, "luminaires": {"middle": {"dimmer": [0.1, 0.8]}}})");
  StartState start;
  start.document = {{"luminaires", {{"left", {{"on", false}, {"cct_kelvin", 3000}}}}}};
  const OptimizeResult r = optimize_lighting(relit, start, targets, {});
  ASSERT_TRUE(r.feasible);
  EXPECT_EQ(r.state["portals"]["south"]["tint"], nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(r.state["luminaires"]["left"]["cct_kelvin"], 3000);  // the start's own keys kept
  EXPECT_EQ(r.state["luminaires"]["left"]["on"], true);
  const double middle = r.state["luminaires"]["middle"]["dimmer"];
  EXPECT_GE(middle, 0.1);
  EXPECT_LE(middle, 0.8);
  const auto lux = testing::readings(relit, r.state);
  ASSERT_EQ(r.targets.size(), 2U);
  for (const TargetOutcome& o : r.targets) {
    EXPECT_TRUE(o.met);
    EXPECT_DOUBLE_EQ(o.achieved, set_value(lux[o.target.set], o.target.kind));
    EXPECT_GE(o.achieved, o.target.value);
  }
  // The middle luminaire's watts come from its IES file (25 W); the others are their mean.
  EXPECT_TRUE(!r.watts_from_data);
  const double watts = 25;
  double power = 0;
  for (const char* name : {"left", "middle", "right"}) {
    power += watts * r.state["luminaires"][name]["dimmer"].get<double>();
  }
  EXPECT_NEAR(r.power_w, power, 1e-9 * power);
  EXPECT_DOUBLE_EQ(r.objective_value, r.power_w);
}

TEST(Optimize, InfeasibleTargetsNameTheOneThatBinds) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const double full = full_desk_mean(relit);
  const DesignTargets targets =
      targets_of(relit.scene(), R"({"sensors": {"desk": {"em_min": )" + std::to_string(3 * full) +
                                    R"(}, "wall": {"em_min": 1}}})");
  const OptimizeResult r = optimize_lighting(relit, {}, targets, {});
  EXPECT_FALSE(r.feasible);
  ASSERT_FALSE(r.binding.empty());
  EXPECT_EQ(r.binding.front(), "desk: em_min");
  EXPECT_FALSE(r.targets[0].met);
  EXPECT_NEAR(r.targets[0].achieved, full, 1e-4 * full);  // everything at full output
  EXPECT_TRUE(r.targets[1].met);
  const nlohmann::json line = optimize_summary(relit.scene(), r);
  EXPECT_EQ(line["feasible"], false);
  EXPECT_EQ(line["binding"][0], "desk: em_min");
}

// Daylight kept (through glass that passes a fifth of it, less than the target): the
// luminaires top up the window's light, at less power than at night, and the state keeps the
// window as the start state has it.
TEST(Optimize, DaylightLinkedDimmingNeedsLessPower) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const double target = 0.6 * full_desk_mean(relit);
  const DesignTargets targets = targets_of(
      relit.scene(), R"({"sensors": {"desk": {"em_min": )" + std::to_string(target) + "}}}");
  StartState start;
  start.document = {{"portals", {{"south", {{"tint", {0.2, 0.2, 0.2}}}}}}};
  const double daylight_alone =
      set_value(testing::readings(relit, {{"portals", start.document["portals"]},
                                          {"luminaires",
                                           {{"left", {{"on", false}}},
                                            {"middle", {{"on", false}}},
                                            {"right", {{"on", false}}}}}})[0],
                TargetKind::kEmMin);
  ASSERT_GT(daylight_alone, 0.2 * target);
  ASSERT_LT(daylight_alone, 0.8 * target);
  const OptimizeResult night = optimize_lighting(relit, start, targets, {});
  OptimizeOptions daylight;
  daylight.daylight = true;
  const OptimizeResult day = optimize_lighting(relit, start, targets, daylight);
  ASSERT_TRUE(night.feasible && day.feasible);
  EXPECT_LT(day.power_w, 0.95 * night.power_w);
  EXPECT_EQ(day.state["portals"], start.document["portals"]);
  EXPECT_EQ(night.state["portals"]["south"]["tint"], nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_GE(day.targets[0].achieved, target);
  EXPECT_NEAR(day.targets[0].achieved, target, 1e-4 * target);  // no more light than asked
  std::printf("desk Em %.1f lx: %.2f W at night, %.2f W with daylight\n", target, night.power_w,
              day.power_w);
}

TEST(Optimize, AFixedLuminaireKeepsItsStartSetting) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const double target = 0.4 * full_desk_mean(relit);
  const DesignTargets targets =
      targets_of(relit.scene(), R"({"sensors": {"desk": {"em_min": )" + std::to_string(target) +
                                    R"(}}, "luminaires": {"right": {"fixed": true}}})");
  StartState start;
  start.document = {{"luminaires", {{"right", {{"dimmer", 0.3}}}}}};
  const OptimizeResult r = optimize_lighting(relit, start, targets, {});
  ASSERT_TRUE(r.feasible);
  EXPECT_EQ(r.state["luminaires"]["right"], nlohmann::json({{"dimmer", 0.3}}));
  EXPECT_FALSE(optimize_summary(relit.scene(), r)["luminaires"].contains("left") == false);
}

// "right" may turn 25° from straight down to light the wall: the local search from the dimmer
// solution against a grid of aims 2.5° apart over the cone (each with its exact dimmers). The
// search may not be worse than the grid by more than 1 %.
TEST(Optimize, AimsWithinAConeComeWithinOnePercentOfAGridOfAims) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const Scene& scene = relit.scene();
  const auto full = testing::readings(relit, {{"portals", {{"south", {{"tint", {0, 0, 0}}}}}}});
  const double wall = 0.8 * set_value(full[1], TargetKind::kEmMin);
  const double desk = 0.3 * set_value(full[0], TargetKind::kEmMin);
  const std::string json = R"({"sensors": {"wall": {"em_min": )" + std::to_string(wall) +
                           R"(}, "desk": {"em_min": )" + std::to_string(desk) +
                           R"(}}, "luminaires": {"right": {"aim_cone_deg": 25}}})";
  const DesignTargets targets = targets_of(scene, json);
  const OptimizeResult r = optimize_lighting(relit, {}, targets, {});
  ASSERT_TRUE(r.feasible);
  EXPECT_GT(r.aim_trials, 0);
  const Vec3 aim = {r.state["luminaires"]["right"]["aim"][0].get<double>(),
                    r.state["luminaires"]["right"]["aim"][1].get<double>(),
                    r.state["luminaires"]["right"]["aim"][2].get<double>()};
  EXPECT_LE(std::acos(-aim.y), 25 * kPi / 180 + 1e-9);

  // The grid: the same model, the right luminaire's column for each aim, the dimmers solved.
  LightingState base = default_lighting_state(scene);
  for (PortalState& p : base.portals) p.tint = {0, 0, 0};
  const std::vector<std::size_t> free = {0, 1, 2}, sets = {0, 1};
  IlluminanceModel model = illuminance_model(relit, base, free, sets);
  DimmerProblem p;
  p.model = &model;
  p.targets = targets.targets;
  p.lo = {0, 0, 0};
  p.hi = {1, 1, 1};
  p.watts = {25, 25, 25};
  const AimCone cone{scene.luminaires[2].aim, 25 * kPi / 180};
  double grid = std::numeric_limits<double>::infinity();
  const double step = 2.5 * kPi / 180;
  int aims = 0;
  for (int a = -10; a <= 10; ++a) {
    for (int b = -10; b <= 10; ++b) {
      const AimOffset o = {a * step, b * step};
      if (std::hypot(o[0], o[1]) > cone.radius_rad + 1e-12) continue;
      LuminaireState l = base.luminaires[2];
      l.aim = aim_in_cone(cone, o);
      l.c0 = reorthogonalised_c0(l.c0, l.aim);
      update_model_column(model, relit, base, 2, l);
      const DimmerSolution s = solve_dimmers(p);
      if (s.feasible) grid = std::min(grid, s.power_w);
      ++aims;
    }
  }
  std::printf("aim search: %.3f W after %d trials; grid of %d aims: %.3f W (%+.2f %%)\n", r.power_w,
              r.aim_trials, aims, grid, 100 * (r.power_w / grid - 1));
  EXPECT_LE(r.power_w, grid * 1.01);
  // Probe's view of the written aim: the targets met.
  for (const TargetOutcome& o : r.targets) EXPECT_TRUE(o.met);
}

TEST(Optimize, RelativeFilesAreRebasedOntoTheOutputFolder) {
  const nlohmann::json doc = {
      {"luminaires", {{"a", {{"distribution", {{"type", "ies"}, {"file", "lum/a.ies"}}}}}}},
      {"portals", {{"w", {{"environment", {{"type", "map"}, {"file", "/abs/sky.exr"}}}}}}}};
  const nlohmann::json out = rebase_relative_files(doc, "/p/states", "/p/out");
  EXPECT_EQ(out["luminaires"]["a"]["distribution"]["file"], "../states/lum/a.ies");
  EXPECT_EQ(out["portals"]["w"]["environment"]["file"], "/abs/sky.exr");
  EXPECT_EQ(rebase_relative_files(doc, "/p/states", "/p/states/"), doc);
}

}  // namespace
}  // namespace relight
