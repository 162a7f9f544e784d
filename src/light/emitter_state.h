// A near-field emitter's part of the lighting state (docs/lighting-state.md, "Emitters").
#pragma once

#include "math/placement.h"
#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

// A near-field emitter: where it is (turned by `rotate_deg` about the vertical axis
// through its pivot, then moved by `translate`, as an exterior placement), how bright and
// which colour, and whether it is on. Needs no new precompute: its light is sampled at run time.
struct EmitterState : Placement {
  double luminance = 0;  // cd/m²
  Rgb color{1, 1, 1};    // luminance-normalised
  bool on = true;
  bool operator==(const EmitterState&) const = default;
};

// An emitter as the scene sets it.
inline EmitterState emitter_state(const Emitter& e) {
  EmitterState s;
  s.luminance = e.luminance;
  s.color = e.color;
  return s;
}

}  // namespace relight
