// One sample of the incident radiance function L(x, ω) for near-field SH lighting (the
// Sun 2005 §3.3): its position x, the SH coefficients l_x of the radiance arriving
// there (RGB, world frame, order² values) and its valid domain, a sphere of radius `radius`
// about x (§3.3.3: only vertices inside it are reconstructed from this sample).
#pragma once

#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

struct IncidentSample {
  Vec3 position;
  double radius = 0;    // valid domain (0 = none: the ICP baseline's samples)
  std::vector<Rgb> sh;  // order² coefficients, cd/m² · (SH basis), world frame
};

}  // namespace relight
