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

std::vector<PixelSun> pixel_suns(const Relighter& relighter, std::size_t portals) {
  std::vector<PixelSun> suns;
  for (std::size_t p = 0; p < portals; ++p) {
    if (const std::optional<PortalSun>& s = relighter.sharp_sun(p)) {
      suns.push_back({static_cast<std::uint32_t>(p), s->direction, s->illuminance});
    }
  }
  return suns;
}

Rgb sun_irradiance(const RayTracer& occluders, const RayTracer& portals,
                   const std::vector<PixelSun>& suns, Vec3 p, Vec3 n) {
  Rgb e;
  for (const PixelSun& s : suns) {
    const double c = dot(n, s.direction);
    if (c <= 0) continue;
    const Vec3 origin = offset_from_surface(p, n);
    const RayHit window = portals.intersect({origin, s.direction});
    if (!window.hit() || window.triangle != s.portal) continue;
    if (occluders.occluded({origin, s.direction})) continue;  // before or past the window
    e += s.illuminance * c;
  }
  return e;
}

}  // namespace relight
