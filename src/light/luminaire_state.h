// A luminaire's part of the lighting state (docs/lighting-state.md, "Luminaires"): on/off,
// dimmer, colour, aim and distribution. Its position is fixed by the precompute.
#pragma once

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/distribution_spec.h"
#include "scene/scene.h"

namespace relight {

struct LuminaireState {
  bool on = true;
  double dimmer = 1;
  Rgb color{1, 1, 1};  // luminance-normalised
  Vec3 aim{0, -1, 0}, c0{1, 0, 0};
  DistributionSpec distribution;
};

// A luminaire as the scene sets it.
inline LuminaireState luminaire_state(const Luminaire& l) {
  return {true, l.dimmer, l.color, l.aim, l.c0, l.distribution};
}

}  // namespace relight
