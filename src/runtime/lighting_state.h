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

// Where an exterior object is this frame: turned by `rotate_deg` about the vertical axis
// through its pivot (counter-clockwise seen from above, the right-handed sense about +y), then
// moved by `translate`; hidden when not visible.
struct ExteriorPlacement {
  Vec3 translate{0, 0, 0};
  double rotate_deg = 0;
  bool visible = true;
  bool operator==(const ExteriorPlacement&) const = default;
};

// What a window shows and how its glass changes it (issue 4, the interior-scene paper §5).
struct PortalState {
  EnvironmentSpec environment;
  Rgb tint{1, 1, 1};
  double frost_deg = 0;
  // Per exterior object (scene order): the state's top-level "exterior", overridden for this
  // portal's shell by the portal's own "exterior".
  std::vector<ExteriorPlacement> exterior;
  bool operator==(const PortalState&) const = default;
};

// A near-field emitter (issue 5): where it is (turned by `rotate_deg` about the vertical axis
// through its pivot, then moved by `translate`, as an exterior placement), how bright and
// which colour, and whether it is on. Needs no new precompute: its light is sampled at run time.
struct EmitterState {
  Vec3 translate{0, 0, 0};
  double rotate_deg = 0;
  double luminance = 0;  // cd/m²
  Rgb color{1, 1, 1};    // luminance-normalised
  bool on = true;
  bool operator==(const EmitterState&) const = default;
};

struct LightingState {
  std::vector<LuminaireState> luminaires;  // scene order
  std::vector<PortalState> portals;        // scene order
  std::vector<EmitterState> emitters;      // scene order
};

LightingState default_lighting_state(const Scene& scene);

// Applies a state document to `state`. `where` names it in messages (a file or
// "message"); relative distribution files resolve against `base_dir`.
void apply_lighting_state(LightingState& state, const Scene& scene, const nlohmann::json& document,
                          const std::string& where, const std::filesystem::path& base_dir);

LightingState load_lighting_state(const Scene& scene, const std::filesystem::path& file);

}  // namespace relight
