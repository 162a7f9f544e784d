// The dimmers that meet the designer's targets, solved exactly as linear programs over the
// illuminance model E = b + A d (design/illuminance_model.h):
//  * Em ≥ / ≤ a value: one row on the set's mean row; E ≥ / ≤ a value: one row per point;
//    U0 ≥ u: E_i ≥ u · Em at every point — linear, since Em is.
//  * "power": minimise Σ w_j d_j (W) over lo_j ≤ d_j ≤ hi_j.
//  * "uniformity": maximise the smallest U0 of the sets with a level target (em_min or e_min),
//    a generalised fractional program solved by Dinkelbach's method (a few linear programs;
//    see solve_dimmers); at the best U0 the power is minimised.
//  * Infeasible targets: a slack per target, in units of its value (a U0 target's in units of
//    u · the set's Em with every free dimmer at its top), and the sum of slacks minimised — the
//    closest state — then the power at that least violation.
// Lower bounds are asked 1e-6 (relative) above their value and upper bounds below, so that the
// relit scene, summed in single precision, still meets them. Tests:
// tests/design/dimmer_program_test.cpp (grid searches over 2–3 dimmers).
#pragma once

#include <span>
#include <vector>

#include "design/design_targets.h"
#include "design/illuminance_model.h"

namespace relight {

struct DimmerProblem {
  const IlluminanceModel* model = nullptr;
  std::span<const Target> targets;
  std::vector<double> lo, hi, watts;  // per free luminaire (model order)
  DesignObjective objective = DesignObjective::kPower;
};

struct DimmerSolution {
  bool feasible = false;
  std::vector<double> dimmers;  // per free luminaire (model order)
  double power_w = 0;           // Σ watts · dimmer
  double violation = 0;         // Σ of the targets' relative slacks (0 when feasible)
  double uniformity = 0;        // "uniformity": the smallest U0 of the level sets (model)
  int iterations = 0;           // simplex iterations of every program solved
  int programs = 0;             // linear programs solved
};

DimmerSolution solve_dimmers(const DimmerProblem& problem);

// A target's quantity over a set's readings (lx): Em, the smallest or largest E, or U0.
double set_value(std::span<const double> lux, TargetKind kind);

// The model's value of `target` at dimmers d: Em, the smallest or largest E, or U0 of its set.
double model_value(const IlluminanceModel& model, const Target& target, std::span<const double> d);

// Whether `a` is better than `b`: less violation first (beyond 1e-9), then the objective.
bool better_solution(const DimmerSolution& a, const DimmerSolution& b, DesignObjective objective);

}  // namespace relight
