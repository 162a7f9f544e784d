// A luminaire's part of the lighting state (docs/lighting-state.md, "Luminaires"): on/off,
// dimmer, colour, aim, distribution, and where it hangs. A state may move a precomputed
// luminaire and add luminaires the scene does not have (the layout); the luminaires' term
// (sources/luminaires/luminaire_lighting.h) lights those at run time.
#pragma once

#include <string>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/distribution_spec.h"
#include "scene/scene.h"

namespace relight {

struct LuminaireState {
  std::string name;
  bool on = true;
  double dimmer = 1;
  Rgb color{1, 1, 1};  // luminance-normalised
  Vec3 aim{0, -1, 0}, c0{1, 0, 0};
  DistributionSpec distribution;
  Vec3 position;  // the photometric centre, m
  // The luminous opening [width, length, height] overriding the file's (Luminaire::size).
  Vec3 size{0, 0, 0};
  bool has_size = false;
};

// A luminaire as the scene sets it.
inline LuminaireState luminaire_state(const Luminaire& l) {
  return {l.name, true,           l.dimmer,   l.color, l.aim,
          l.c0,   l.distribution, l.position, l.size,  l.has_size};
}

// The scene's luminaire a state describes: what a fresh precompute of the layout would
// store, and what the reference tracer places (dimmer 0 when off).
inline Luminaire scene_luminaire(const LuminaireState& s) {
  Luminaire l;
  l.name = s.name;
  l.position = s.position;
  l.aim = s.aim;
  l.c0 = s.c0;
  l.color = s.color;
  l.dimmer = s.on ? s.dimmer : 0;
  l.size = s.size;
  l.has_size = s.has_size;
  l.distribution = s.distribution;
  l.where = s.distribution.where;
  return l;
}

}  // namespace relight
