// The run-time lighting state (docs/lighting-state.md): what a designer changes without
// a new precompute — per luminaire on/off, dimmer, colour or colour temperature, aim and
// distribution. Applied on top of the scene's own values, so a state file names only what
// it changes. A luminaire's position is fixed by the precompute: moving it is refused.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace relight {

struct LuminaireState {
  bool on = true;
  double dimmer = 1;
  Rgb color{1, 1, 1};  // luminance-normalised
  Vec3 aim{0, -1, 0}, c0{1, 0, 0};
  DistributionSpec distribution;
};

struct LightingState {
  std::vector<LuminaireState> luminaires;  // scene order
};

LightingState default_lighting_state(const Scene& scene);

// Applies a state document to `state`. `where` names it in messages (a file or
// "message"); relative distribution files resolve against `base_dir`.
void apply_lighting_state(LightingState& state, const Scene& scene, const nlohmann::json& document,
                          const std::string& where, const std::filesystem::path& base_dir);

LightingState load_lighting_state(const Scene& scene, const std::filesystem::path& file);

}  // namespace relight
