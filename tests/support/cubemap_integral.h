// ∫ L dω of a cubemap of radiance (photometric Y), with exact per-texel solid angles:
// what energy-conserving rasterisations must preserve.
#pragma once

#include <vector>

#include "math/cubemap.h"
#include "math/rgb.h"

namespace relight::testing {

inline double cube_integral(const std::vector<Rgb>& cube, int n) {
  const std::vector<double>& omega = cubemap_solid_angles(n);
  double sum = 0;
  for (std::size_t t = 0; t < cube.size(); ++t) {
    const CubemapTexel c = cubemap_texel_from_index(n, t);
    sum += luminance(cube[t]) * omega[c.j * n + c.i];
  }
  return sum;
}

}  // namespace relight::testing
