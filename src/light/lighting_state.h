// The run-time lighting state (docs/lighting-state.md): what a designer changes without a new
// precompute, one part per kind of light in the scene format's words (luminaires, portals,
// emitters, the top-level environment), the movable objects' placements and the materials. Each
// kind's run-time term takes its own part (engine/light_term.h); runtime/lighting_state.h reads
// a state document into it.
#pragma once

#include <optional>
#include <vector>

#include "light/emitter_state.h"
#include "light/luminaire_state.h"
#include "light/portal_state.h"
#include "math/placement.h"
#include "scene/environment_spec.h"
#include "scene/scene.h"

namespace relight {

struct LightingState {
  // The scene's luminaires (scene order), then those the state adds.
  std::vector<LuminaireState> luminaires;
  std::vector<PortalState> portals;       // scene order
  std::vector<EmitterState> emitters;     // scene order
  std::vector<MovablePlacement> objects;  // movable objects, scene order
  // The scene's materials with the state's edits (albedo, metallic, roughness), scene order. Window
  // glass is not edited here (its look is its portal's tint and frost).
  std::vector<Material> materials;
  // The top-level environment: swapped, rotated or its sky changed; present exactly when the scene
  // has one.
  std::optional<EnvironmentSpec> environment;
  // The project's site (the scene's, or the state's "site"): every environment above is put there.
  std::optional<Site> site;
};

// The true north of a state's site (0 without one): the clockwise angle from −z.
inline double north_deg(const LightingState& state) {
  return state.site ? state.site->north_deg : 0;
}

// The scene's own values: every light as the scene sets it, the objects where it places them.
LightingState default_lighting_state(const Scene& scene);

}  // namespace relight
