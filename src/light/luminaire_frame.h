// A luminaire placed in the world: its loaded photometry, its photometric frame and
// its colour and dimming, answering "how many candela (RGB) toward this world
// direction". Frame convention (docs/scene-format.md): γ = 0 along aim, C0 along c0,
// C90 = cross(c0, aim), so C angles run counter-clockwise seen from above for a
// downlight, as in IES LM-63 type C.
#pragma once

#include <vector>

#include "light/distribution.h"
#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

struct PlacedLuminaire {
  Vec3 position;
  Vec3 aim, c0, c90;
  Rgb rgb_scale;  // color (luminance-normalised) × dimmer
  Distribution distribution;

  // Direction in the photometric frame: (sinγ cosC, sinγ sinC, cosγ).
  Vec3 to_photometric(Vec3 world_dir) const {
    return {dot(world_dir, c0), dot(world_dir, c90), dot(world_dir, aim)};
  }
  // RGB intensity (candela per channel) toward a unit world direction.
  Rgb intensity_toward(Vec3 world_dir) const {
    return rgb_scale * distribution.intensity(to_photometric(world_dir));
  }
};

PlacedLuminaire place_luminaire(const Luminaire& luminaire);
std::vector<PlacedLuminaire> place_luminaires(const Scene& scene);

}  // namespace relight
