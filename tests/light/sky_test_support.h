// What the sky tests share: an independent quadrature of a sky's horizontal illuminance.
#pragma once

#include <cmath>

#include "light/sky_model.h"

namespace relight {

// Independent check of E_h = ∫ L cos Z dω: midpoint rule in (cos Z, azimuth), the azimuth grid
// offset from the sun's (error O(h²), h = 1/n).
inline double midpoint_horizontal_illuminance(const SkyModel& sky, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double mu = (k + 0.5) / n, s = std::sqrt(1 - mu * mu);
    double ring = 0;
    for (int j = 0; j < 2 * n; ++j) {
      const double az = 0.123 + 2 * kPi * (j + 0.5) / (2 * n);
      ring += sky_diffuse_luminance(sky, {s * std::sin(az), mu, -s * std::cos(az)});
    }
    sum += mu * ring;
  }
  return sum * (1.0 / n) * (2 * kPi / (2 * n));
}

}  // namespace relight
