// One precomputed design room (tests/support/design_room.h) shared by a test program's
// tests, with the helpers they share: the scene relit by a state document and a set's readings.
#pragma once

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "design/illuminance_model.h"
#include "runtime/relit_scene.h"
#include "support/design_room.h"

namespace relight::testing {

inline const DesignRoom& design_room() {
  static const std::unique_ptr<DesignRoom> room = std::make_unique<DesignRoom>();
  return *room;
}

// Each sensor set's readings (lx, the Y of RGB as `relight probe` prints) under `document`.
inline std::vector<std::vector<double>> readings(RelitScene& relit,
                                                 const nlohmann::json& document) {
  const Scene& scene = relit.scene();
  LightingState state = default_lighting_state(scene);
  apply_lighting_state(state, scene, document, "test state", design_room().dir.path());
  relit.apply(state);
  return sensor_set_lux(relit);
}

}  // namespace relight::testing
