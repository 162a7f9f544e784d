// A window's part of the lighting state (docs/lighting-state.md, "Portals"): the environment
// seen through it, its glass, and where the exterior objects in front of it are.
#pragma once

#include <optional>
#include <vector>
#include "math/placement.h"
#include "math/rgb.h"

#include "scene/environment_spec.h"
#include "scene/scene.h"

namespace relight {

// Where an exterior object is this frame: turned by `rotate_deg` about the vertical axis
// through its pivot (counter-clockwise seen from above, the right-handed sense about +y), then
// moved by `translate`; hidden when not visible.
using ExteriorPlacement = MovablePlacement;

// What a window shows and how its glass changes it (Yue et al. 2009 §5).
struct PortalState {
  EnvironmentSpec environment;
  Rgb tint{1, 1, 1};
  double frost_deg = 0;
  std::optional<Glazing> glazing;  // none: an opening with its tint alone
  // Per exterior object (scene order): the state's top-level "exterior", overridden for this
  // portal's shell by the portal's own "exterior".
  std::vector<ExteriorPlacement> exterior;
  bool operator==(const PortalState&) const = default;
};

// A portal as the scene sets it, with every one of `exterior_objects` where the scene put it.
inline PortalState portal_state(const Portal& p, std::size_t exterior_objects) {
  return {p.environment, p.tint, p.frost_deg, p.glazing,
          std::vector<ExteriorPlacement>(exterior_objects)};
}

}  // namespace relight
