#include "light/luminaire_frame.h"

namespace relight {

PlacedLuminaire place_luminaire(const Luminaire& l) {
  return {l.position, photometric_frame(l.aim, l.c0), l.color * l.dimmer,
          load_distribution(l.distribution)};
}

std::vector<PlacedLuminaire> place_luminaires(const Scene& scene) {
  std::vector<PlacedLuminaire> out;
  out.reserve(scene.luminaires.size());
  for (const Luminaire& l : scene.luminaires) out.push_back(place_luminaire(l));
  return out;
}

}  // namespace relight
