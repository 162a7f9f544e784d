#include "light/luminaire_frame.h"

#include <cmath>

namespace relight {

Vec3 reorthogonalised_c0(Vec3 c0, Vec3 aim) {
  Vec3 t = c0 - aim * dot(c0, aim);
  if (length(t) < 1e-6) t = std::abs(aim.x) > 0.999 ? Vec3{0, 0, -1} : Vec3{1, 0, 0};
  t = t - aim * dot(t, aim);
  return normalize(t);
}

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
