// Exact direct light at the surface point seen by each pixel: the same direct geometry
// the precompute stores per receiver (sources/luminaire/luminaire_direct.h: visibility of the
// luminous opening, cos θ / d²) evaluated at the hit instead of at vertices, times the
// current distribution, aim, colour and dimming. With the per-vertex interreflected light
// interpolated as usual, images show sharp shadows and beam edges that per-vertex
// (Gouraud) shading blurs over one mesh edge — past Dobashi et al. 1995, whose
// images are per-vertex throughout.
#pragma once

#include <cstdint>
#include <vector>

#include "light/luminaire_frame.h"
#include "runtime/relighter.h"
#include "scene/scene.h"
#include "trace/ray_tracer.h"

namespace relight {

struct PixelLight {
  Vec3 position;
  PhotometricFrame frame;
  Rgb rgb;  // colour × dimmer (0 when off)
  const Distribution* distribution = nullptr;
  std::vector<Vec3> opening;  // sample offsets on the luminous opening
};

// The luminaires as the relighter's current state sets them.
std::vector<PixelLight> pixel_lights(const Scene& scene, const Relighter& relighter,
                                     int opening_samples = 16);

// Direct irradiance (lux per channel) at p with unit normal n.
Rgb exact_direct_irradiance(const RayTracer& occluders, const std::vector<PixelLight>& lights,
                            Vec3 p, Vec3 n);

}  // namespace relight
