#include "sources/environment/compact_light.h"

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
  return disc_irradiance(sources, n, [&](const CompactSource& s) {
    return compact_fraction(occluders, s, origin, penumbra);
  });
}

SeenLight compact_seen_from(const Occluders& occluders, const CompactSource& source, Vec3 origin,
                            Vec3 n, bool with_luminance) {
  return disc_seen_from(source, n, with_luminance, [&](const CompactSource& s) {
    return compact_fraction(occluders, s, origin);
  });
}

}  // namespace relight
