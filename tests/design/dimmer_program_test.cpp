// The dimmer programs (design/dimmer_program.h) against brute-force grid searches over the dimmers
// of the design room's luminaires (within 0.5 %), and their optimum against the relit scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "design/dimmer_program.h"
#include "design_room_fixture.h"

namespace relight {
namespace {

using testing::design_room;

constexpr std::size_t kDesk = 0, kWall = 1;

struct Modelled {
  RelitScene relit{design_room().rlt, std::nullopt};
  IlluminanceModel model;
  explicit Modelled(std::vector<std::size_t> free) {
    LightingState base = default_lighting_state(relit.scene());
    for (PortalState& p : base.portals) p.tint = {0, 0, 0};
    for (LuminaireState& l : base.luminaires) l.on = false;
    const std::vector<std::size_t> sets = {kDesk, kWall};
    model = illuminance_model(relit, base, free, sets);
  }
  double value(std::size_t set, TargetKind kind, std::span<const double> d) const {
    return model_value(model, {set, kind, 0}, d);
  }
  // Every dimmer free in 0..1.
  DimmerProblem problem(std::span<const Target> targets, std::vector<double> watts) const {
    DimmerProblem p;
    p.model = &model;
    p.targets = targets;
    p.lo.assign(model.free.size(), 0.0);
    p.hi.assign(model.free.size(), 1.0);
    p.watts = std::move(watts);
    return p;
  }
};

bool meets(const IlluminanceModel& model, std::span<const Target> targets,
           std::span<const double> d) {
  for (const Target& t : targets) {
    const double v = model_value(model, t, d);
    if (is_lower_bound(t.kind) ? v < t.value : v > t.value) return false;
  }
  return true;
}

// Three luminaires, targets on both sets that full output meets: the power optimum meets them
// (in the relit scene too) and is within 0.5 % of — and never above — a grid search (left and
// middle in steps of 0.002; right, for each, the least dimmer that meets every row, exactly).
TEST(DimmerProgram, ThePowerOptimumMeetsTheTargetsWithinHalfAPercentOfAGridSearch) {
  const Modelled m({0, 1, 2});
  const std::vector<double> ones = {1, 1, 1};
  const std::vector<Target> targets = {
      {kDesk, TargetKind::kEmMin, 0.6 * m.value(kDesk, TargetKind::kEmMin, ones)},
      {kDesk, TargetKind::kU0Min, 0.8 * m.value(kDesk, TargetKind::kU0Min, ones)},
      {kWall, TargetKind::kEmMin, 0.4 * m.value(kWall, TargetKind::kEmMin, ones)}};
  const DimmerProblem p = m.problem(targets, {30, 25, 40});
  const DimmerSolution s = solve_dimmers(p);
  ASSERT_TRUE(s.feasible);
  EXPECT_TRUE(meets(m.model, targets, s.dimmers));
  EXPECT_EQ(s.violation, 0);

  double grid = std::numeric_limits<double>::infinity();
  for (int a = 0; a <= 500; ++a) {
    for (int b = 0; b <= 500; ++b) {
      const double d0 = a * 0.002, d1 = b * 0.002;
      // Every row is linear in d2: lo ≤ d2 ≤ hi.
      double lo = 0, hi = 1;
      for (const Target& t : targets) {
        const ModelSet& set = m.model.rows_of(t.set);
        const auto bound = [&](double c0, double c1, double c2, double rhs) {  // c·d ≥ rhs
          const double rest = rhs - c0 * d0 - c1 * d1;
          if (c2 > 0)
            lo = std::max(lo, rest / c2);
          else if (c2 < 0)
            hi = std::min(hi, rest / c2);
          else if (rest > 0)
            hi = -1;
        };
        double mean[4] = {0, 0, 0, 0};
        for (std::size_t r = set.first; r < set.first + set.count; ++r) {
          for (std::size_t j = 0; j < 3; ++j) mean[j] += m.model.column(r, j) / set.count;
          mean[3] += m.model.base[r] / set.count;
        }
        if (t.kind == TargetKind::kEmMin) bound(mean[0], mean[1], mean[2], t.value - mean[3]);
        if (t.kind == TargetKind::kU0Min) {
          for (std::size_t r = set.first; r < set.first + set.count; ++r) {
            bound(m.model.column(r, 0) - t.value * mean[0],
                  m.model.column(r, 1) - t.value * mean[1],
                  m.model.column(r, 2) - t.value * mean[2], t.value * mean[3] - m.model.base[r]);
          }
        }
      }
      if (lo <= hi) grid = std::min(grid, 30 * d0 + 25 * d1 + 40 * lo);
    }
  }
  std::printf("power optimum %.4f W, grid search %.4f W (%.3f %% above)\n", s.power_w, grid,
              100 * (grid / s.power_w - 1));
  EXPECT_LE(s.power_w, grid * (1 + 1e-5));  // the programs' margin is 1e-6 of each target
  EXPECT_GE(s.power_w, grid * (1 - 0.005));

  // The relit scene at the optimum meets the targets as the model does.
  RelitScene relit(design_room().rlt, std::nullopt);
  nlohmann::json doc = {{"portals", {{"south", {{"tint", {0, 0, 0}}}}}}};
  const char* names[] = {"left", "middle", "right"};
  for (std::size_t j = 0; j < 3; ++j) doc["luminaires"][names[j]]["dimmer"] = s.dimmers[j];
  const auto lux = testing::readings(relit, doc);
  for (const Target& t : targets) {
    const double v = set_value(lux[t.set], t.kind);
    EXPECT_GE(v, t.value) << target_key(t.kind);
    EXPECT_NEAR(v, model_value(m.model, t, s.dimmers), 1e-5 * t.value);
  }
}

// Two luminaires, "uniformity" with a level on the desk: the bisected U0 is the best of a
// grid of the two dimmers in steps of 0.001 (never below it by more than the bisection's
// width, and not above it by more than 0.5 %).
TEST(DimmerProgram, TheUniformityOptimumMatchesAGridSearchWithinHalfAPercent) {
  const Modelled m({0, 2});
  const std::vector<double> ones = {1, 1};
  const std::vector<Target> targets = {
      {kDesk, TargetKind::kEmMin, 0.5 * m.value(kDesk, TargetKind::kEmMin, ones)}};
  DimmerProblem p = m.problem(targets, {1, 1});
  p.objective = DesignObjective::kUniformity;
  const DimmerSolution s = solve_dimmers(p);
  ASSERT_TRUE(s.feasible);
  EXPECT_TRUE(meets(m.model, targets, s.dimmers));
  double grid = 0;
  for (int a = 0; a <= 1000; ++a) {
    for (int b = 0; b <= 1000; ++b) {
      const std::vector<double> d = {a * 0.001, b * 0.001};
      if (!meets(m.model, targets, d)) continue;
      grid = std::max(grid, m.value(kDesk, TargetKind::kU0Min, d));
    }
  }
  const double u0 = m.value(kDesk, TargetKind::kU0Min, s.dimmers);
  std::printf("uniformity optimum U0 %.5f, grid search %.5f; %d programs\n", u0, grid, s.programs);
  EXPECT_NEAR(s.uniformity, u0, 1e-12);
  EXPECT_GE(u0, grid - 2e-5);
  EXPECT_LE(u0, grid * 1.005);
}

// A desk mean above what every luminaire at full output gives: infeasible, and the closest
// state (least relative violation) has every luminaire at its top.
TEST(DimmerProgram, UnreachableTargetsGiveTheClosestStateAndItsViolation) {
  const Modelled m({0, 1, 2});
  const std::vector<double> ones = {1, 1, 1};
  const double full = m.value(kDesk, TargetKind::kEmMin, ones);
  const std::vector<Target> targets = {{kDesk, TargetKind::kEmMin, 1.5 * full}};
  const DimmerProblem p = m.problem(targets, {1, 1, 1});
  const DimmerSolution s = solve_dimmers(p);
  EXPECT_FALSE(s.feasible);
  for (const double d : s.dimmers) EXPECT_NEAR(d, 1, 1e-5);  // the power stage may give 1e-7
  EXPECT_NEAR(s.violation, (1.5 * full * (1 + 1e-6) - full) / (1.5 * full), 1e-6);
}

// A maximum below a minimum elsewhere is met as closely as the two allow, at the least power.
TEST(DimmerProgram, DimmerBoundsAndUpperTargetsHold) {
  const Modelled m({0, 1, 2});
  const std::vector<double> ones = {1, 1, 1};
  const std::vector<Target> targets = {
      {kDesk, TargetKind::kEmMin, 0.5 * m.value(kDesk, TargetKind::kEmMin, ones)},
      {kWall, TargetKind::kEMax, 0.6 * m.value(kWall, TargetKind::kEMax, ones)}};
  DimmerProblem p = m.problem(targets, {1, 1, 1});
  p.lo = {0.2, 0, 0};
  p.hi = {0.9, 0.5, 1};
  const DimmerSolution s = solve_dimmers(p);
  ASSERT_TRUE(s.feasible);
  EXPECT_TRUE(meets(m.model, targets, s.dimmers));
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_GE(s.dimmers[j], p.lo[j] - 1e-12);
    EXPECT_LE(s.dimmers[j], p.hi[j] + 1e-12);
  }
}

}  // namespace
}  // namespace relight
