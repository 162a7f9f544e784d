#include "light/disc_visibility.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace relight {

DiscDirections disc_directions(const SunDisc& disc) {
  DiscDirections out;
  for (int i = 0; i < kDiscRimDirections; ++i) {
    const double a = 2 * kPi * i / kDiscRimDirections;
    out.directions[static_cast<std::size_t>(i)] =
        sun_disc_direction(disc, std::cos(a), std::sin(a));
  }
  // The penumbra: equal areas of the disc.
  const std::vector<Vec3> spiral = sun_disc_spiral(disc, kDiscPenumbraDirections);
  std::copy(spiral.begin(), spiral.end(), out.directions.begin() + kDiscRimDirections);
  return out;
}

bool disc_may_reach(const SunDisc& disc, Vec3 origin, Vec3 centre, double radius) {
  const Vec3 v = centre - origin;
  const double along = dot(v, disc.direction);
  if (along < -radius) return false;
  const double across = length(v - disc.direction * along);
  return across <= radius + length(v) * disc.tan_angular_radius * 1.01 + 1e-9;
}

}  // namespace relight
