// Inverse lighting design (`relight optimize`; the future work of Dobashi et al. 1995, §6): from
// the designer's targets (design/design_targets.h) and a start state, the luminaire settings that
// meet them — the dimmers exactly (design/dimmer_program.h over the linear illuminance model,
// design/illuminance_model.h), the aims within their cones by a local search from that solution
// (design/aim_search.h) — written as a lighting state document (docs/lighting-state.md) that
// `probe`, `render` and the studio load as it is.
//
// The document written is the start document with, for every free luminaire, "on": true and
// its "dimmer" (and "aim" and "c0" where it turned), and — unless daylight is included — every
// portal's "tint" [0, 0, 0]: the design is for electric light alone, so the windows are dark in
// the state that reproduces it. With daylight (OptimizeOptions::daylight) the start state's
// skies light the room as they are and the luminaires top them up (daylight-linked dimming).
// The achieved values are read from the scene relit with that document, as `relight probe`
// reads them. Tests: tests/design/optimize_test.cpp, tests/cli/optimize_command_test.cpp.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/design_targets.h"
#include "runtime/relit_scene.h"

namespace relight {

struct OptimizeOptions {
  bool daylight = false;  // keep the start state's skies (else the windows are dark)
};

struct TargetOutcome {
  Target target;
  double achieved = 0;   // lx, or U0
  bool met = false;      // within 1e-6 (relative) of the target
  bool binding = false;  // at its bound (within 1e-4 relative) or violated
  double violation = 0;  // relative shortfall or excess, 0 when met
};

// nlohmann::json's noexcept move calls assert_invariant, which clang-tidy 14 cannot prove
// non-throwing:
// NOLINTNEXTLINE(bugprone-exception-escape)
struct OptimizeResult {
  bool feasible = false;
  DesignObjective objective = DesignObjective::kPower;
  double objective_value = 0;   // W (Σ watts · dimmer of the free luminaires), or the smallest U0
  double power_w = 0;           // Σ watts · dimmer of the free luminaires
  bool watts_from_data = true;  // every free luminaire's watts came from "power_w" or its file
  int iterations = 0;           // simplex iterations, every program
  int aim_trials = 0;           // aims tried by the local search
  double seconds = 0;
  std::vector<TargetOutcome> targets;
  std::vector<std::string> binding;  // infeasible: violated targets, worst first; else at bound
  nlohmann::json state;              // the lighting state document
};

// The state the design starts from: its document (`{}`: the scene's own), the folder its
// relative files resolve against, and its name in messages.
struct StartState {
  nlohmann::json document = nlohmann::json::object();
  std::filesystem::path dir = ".";
  std::string where = "start state";
};

// Relights `relit`; leaves it lit by the result.
OptimizeResult optimize_lighting(RelitScene& relit, const StartState& start,
                                 const DesignTargets& targets, const OptimizeOptions& options);

// The one JSON line `relight optimize` prints (docs/optimize.md): feasible, objective,
// iterations, seconds, binding and per target the achieved value.
nlohmann::json optimize_summary(const Scene& scene, const OptimizeResult& result);

// `document` with every relative "file" (distributions, environment maps) made relative to
// `to` instead of `from`, so it still loads after being written into another folder.
nlohmann::json rebase_relative_files(nlohmann::json document, const std::filesystem::path& from,
                                     const std::filesystem::path& to);

}  // namespace relight
