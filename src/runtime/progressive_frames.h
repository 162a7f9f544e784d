// How a lighting state is shown: the frames the studio sends for it and `relight bench
// --edits` times, decided in one place. The first frame never waits for a bounce: a material
// edit shows its light reflected once (Relighter::set_material_bounces(0)), a luminaire moved
// or added its exact direct light with the nearest stored luminaire's interreflection
// (Relighter::set_layout_bounce(false)). When that frame is not the converged light, the
// converged frame follows. Pinned by tests/runtime/progressive_frames_test.cpp.
#pragma once

#include <functional>

#include "light/lighting_state.h"
#include "runtime/relit_scene.h"

namespace relight {

// Relights `relit` with `state` in the frames it is shown in; `frame(converged)` runs after
// each, while `relit` holds that frame's light. Returns the number of frames (1 or 2). The
// relighter's bounce settings are restored to the converged ones on return and on a throw.
int show_progressively(RelitScene& relit, const LightingState& state,
                       const std::function<void(bool converged)>& frame);

}  // namespace relight
