#include "render/pixel_direct.h"

#include "sources/luminaire/luminaire_direct.h"

namespace relight {

std::vector<PixelLight> pixel_lights(const Scene& scene, const Relighter& relighter,
                                     int opening_samples) {
  std::vector<PixelLight> lights;
  const LightingState& state = relighter.state();
  for (std::size_t j = 0; j < scene.luminaires.size(); ++j) {
    const LuminaireState& s = state.luminaires[j];
    const Distribution& d = relighter.distribution(j);
    PixelLight l{scene.luminaires[j].position,
                 photometric_frame(s.aim, s.c0),
                 s.on ? s.color * s.dimmer : Rgb{},
                 &d,
                 {}};
    l.opening = opening_sample_offsets(luminaire_opening(scene.luminaires[j], d.opening()), l.frame,
                                       opening_samples);
    lights.push_back(std::move(l));
  }
  return lights;
}

Rgb exact_direct_irradiance(const RayTracer& occluders, const std::vector<PixelLight>& lights,
                            Vec3 p, Vec3 n) {
  Rgb e;
  std::uint64_t rays = 0;
  for (const PixelLight& l : lights) {
    if (max_component(l.rgb) <= 0) continue;
    const DirectFactor f = direct_factor(occluders, p, n, l.position, l.opening, rays);
    if (f.factor <= 0) continue;
    const Vec3 w = f.direction;
    e += l.rgb * (l.distribution->intensity(l.frame.to_photometric(w)) * f.factor);
  }
  return e;
}

}  // namespace relight
