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

#include "runtime/relighter.h"
#include "scene/scene.h"
#include "trace/ray_tracer.h"

namespace relight {

// The luminaires as the relighter's current state sets them.
std::vector<LuminaireLight> pixel_lights(const Scene& scene, const Relighter& relighter,
                                         int opening_samples = 16);

}  // namespace relight
