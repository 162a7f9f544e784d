// EN 12464-1 checks of the scene's task areas (`relight probe --check`): for every sensor set with
// a "task" (docs/scene-format.md), the maintained average illuminance Ē, the uniformity U0 = Emin/Ē
// and UGR at each of its observers (render/glare.h), each against its requirement. Maintained
// values: the state's electric lighting (luminaires and emitters) times the scene's maintenance
// factor (CIE 97: MF = LLMF·LSF·LMF·RSMF; undeclared, 1), daylight as it is
// (runtime/lighting_state.h maintained_state). UGR with no luminaire in view of an observer passes
// (there is nothing to rate). Pinned by tests/cli/probe_check_test.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "runtime/relit_scene.h"

namespace relight {

struct ObserverCheck {
  TaskObserver observer;
  std::optional<double> ugr;  // none: no luminaire in view
  bool pass = true;
};

struct TaskCheck {
  std::string name;  // the sensor set's
  TaskRequirements required;
  double e_avg = 0, e_min = 0, u0 = 0;  // maintained, lx
  bool em_pass = true, u0_pass = true;
  std::vector<ObserverCheck> observers;
};

struct TaskChecks {
  double maintenance_factor = 1;
  bool declared = false;  // whether the scene declares it
  std::vector<TaskCheck> tasks;
};

// Lights `scene` with its current state maintained, checks every task, and restores the state.
TaskChecks check_tasks(RelitScene& scene);

}  // namespace relight
