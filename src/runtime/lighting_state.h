// Reading a lighting state document (docs/lighting-state.md) into the run-time lighting state
// (light/lighting_state.h), applied on top of the scene's own values, so a state file names only
// what it changes; and what follows from a state (maintained, the scene it lights). A luminaire
// may move anywhere inside the scene's bounds, and a name the scene does not have adds one
// (it needs "position" and "distribution").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "light/lighting_state.h"
#include "scene/scene.h"

namespace relight {

// Applies a state document to `state`. `where` names it in messages (a file or
// "message"); relative distribution files resolve against `base_dir`.
void apply_lighting_state(LightingState& state, const Scene& scene, const nlohmann::json& document,
                          const std::string& where, const std::filesystem::path& base_dir);

LightingState load_lighting_state(const Scene& scene, const std::filesystem::path& file);

// The state as its electric lighting is maintained (CIE 97, EN 12464-1): every luminaire's
// dimmer and every emitter's luminance times the maintenance factor `mf`; daylight as it is.
LightingState maintained_state(LightingState state, double mf);

// The scene as `state` lights it, for code that reads a Scene (the reference tracer): each
// luminaire where the state hangs it, with its aim, C0, distribution, colour and dimmer (0 when
// off), then the luminaires the state adds; each portal's environment,
// tint and frost, the top-level environment; the movable objects placed into `geometry` (hidden
// ones left out, the scene's `objects` then empty). Emitters and exterior objects keep the scene's
// geometry: their placements are the state's (place_emitters, placed_exterior); the materials as
// edited.
Scene scene_with_state(const Scene& scene, const LightingState& state);

}  // namespace relight
