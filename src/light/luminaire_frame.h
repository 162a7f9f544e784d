// The photometric frame, built here and nowhere else, and a luminaire placed in the world:
// its loaded photometry, its frame and its colour and dimming, answering "how many candela
// (RGB) toward this world direction". Frame convention (docs/scene-format.md): γ = 0 along
// aim, C0 along c0, C90 = cross(c0, aim), so C angles run counter-clockwise seen from above for a
// downlight, as in IES LM-63 type C — a left-handed frame (docs/decisions.md, "The photometric
// frame is left-handed"; pinned by tests/sources/luminaires/luminaire_sh_test.cpp).
#pragma once

#include <vector>

#include "light/distribution.h"
#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

struct PhotometricFrame {
  Vec3 aim{0, -1, 0}, c0{1, 0, 0}, c90{0, 0, -1};

  // Direction in the photometric frame: (sinγ cosC, sinγ sinC, cosγ).
  Vec3 to_photometric(Vec3 world_dir) const {
    return {dot(world_dir, c0), dot(world_dir, c90), dot(world_dir, aim)};
  }
};

// The frame of a luminaire aimed along `aim` with C0 along `c0` (unit, not parallel).
constexpr PhotometricFrame photometric_frame(Vec3 aim, Vec3 c0) {
  return {aim, c0, cross(c0, aim)};
}

// C0 kept orthogonal to a new aim (unit): the C0 half-plane turns with the luminaire; a c0
// parallel to the aim becomes world +x, or −z for an aim along x (docs/lighting-state.md).
Vec3 reorthogonalised_c0(Vec3 c0, Vec3 aim);

// A luminaire is a point at its photometric centre: a shadow ray toward it stops this far
// short of it (so that it does not meet the luminaire's own housing or the surface it sits on),
// and a point closer than this receives nothing from it, m.
inline constexpr double kLightMargin = 1e-4;

struct PlacedLuminaire {
  Vec3 position;
  PhotometricFrame frame;
  Rgb rgb_scale;  // color (luminance-normalised) × dimmer
  Distribution distribution;

  // RGB intensity (candela per channel) toward a unit world direction.
  Rgb intensity_toward(Vec3 world_dir) const {
    return rgb_scale * distribution.intensity(frame.to_photometric(world_dir));
  }
};

PlacedLuminaire place_luminaire(const Luminaire& luminaire);
std::vector<PlacedLuminaire> place_luminaires(const Scene& scene);

}  // namespace relight
