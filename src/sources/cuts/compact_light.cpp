#include "sources/cuts/compact_light.h"

namespace relight {

double compact_fraction(const Occluders& occluders, const CompactSource& source, Vec3 origin,
                        bool penumbra) {
  return disc_fraction(
      source.disc, source.directions,
      [&](Vec3 w) {
        return !occluders.occluded({origin, w});
      },
      penumbra);
}

Rgb compact_irradiance(const Occluders& occluders, std::span<const CompactSource> sources,
                       Vec3 origin, Vec3 n, bool penumbra) {
  Rgb e;
  for (const CompactSource& s : sources) {
    const double c = dot(n, s.disc.direction);
    if (c <= 0) continue;
    const double f = compact_fraction(occluders, s, origin, penumbra);
    if (f > 0) e += s.illuminance * (f * c);
  }
  return e;
}

}  // namespace relight
