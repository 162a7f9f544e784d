#include "light/disc_visibility.h"

#include <algorithm>
#include <cmath>

namespace relight {

DiscDirections disc_directions(const SunDisc& disc) {
  DiscDirections out;
  for (int i = 0; i < kDiscRimDirections; ++i) {
    const double a = 2 * kPi * i / kDiscRimDirections;
    out.directions[static_cast<std::size_t>(i)] =
        sun_disc_direction(disc, std::cos(a), std::sin(a));
  }
  // The penumbra: equal areas of the disc, each point with its reflection through the centre
  // (its tangent-plane offset negated).
  const double golden = kPi * (3 - std::sqrt(5.0));
  constexpr int kPairs = kDiscPenumbraDirections / 2;
  for (int i = 0; i < kPairs; ++i) {
    const double radius = std::sqrt((i + 0.5) / kPairs), a = golden * i;
    const double x = radius * std::cos(a), y = radius * std::sin(a);
    const auto k = static_cast<std::size_t>(kDiscRimDirections + 2 * i);
    out.directions[k] = sun_disc_direction(disc, x, y);
    out.directions[k + 1] = sun_disc_direction(disc, -x, -y);
  }
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
