// The fraction of a disc source seen from a point: the window's sun (sources/portals/portal_sun.h)
// and the compact sources of a top-level environment (sources/environment/compact_light.h), each
// with its own test of one direction (`seen`). Two steps: 9 directions — the disc's centre and 8
// points on its rim — and when they disagree (the point is in a penumbra) 80 directions: 40
// spread evenly over the disc's area (a Vogel spiral, as light/sky_model.h sun_disc_spiral) and
// their reflections through its centre. The pairs put a straight edge's 50 % point exactly where
// the edge crosses the disc's centre (64 spiral points alone put it up to 0.039 radii off: 0.44 mm
// at 2.6 m from a 0.5° source's occluder, over a pixel of a room's render), and f is within 0.045
// of the closed form for a straight edge at any offset and direction (64 spiral points: 0.049; 64
// in pairs: 0.052; 96 in pairs: 0.040); a penumbra is narrow, so its few points can afford them. A
// straight edge that cuts off less than the segment between two neighbouring rim points (1.2 % of
// the disc) goes unseen. Unoccluded, the mean of n·ω over the disc is n·s exactly (∫_disc ω dω =
// s·π sin²r), so E = E_n · f · max(0, n · s) with f = 1 is the closed form.
// Pinned by tests/sources/portals/portal_sun_test.cpp (f at and across a window's edge against the
// closed form).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "light/seen_light.h"
#include "light/sky_model.h"
#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

inline constexpr int kDiscRimDirections = 8;
inline constexpr int kDiscPenumbraDirections = 80;  // 40 and their reflections

// A disc's directions: its rim, then the penumbra's spiral.
struct DiscDirections {
  std::array<Vec3, kDiscRimDirections + kDiscPenumbraDirections> directions{};
};

DiscDirections disc_directions(const SunDisc& disc);

// Σ over `sources` (each with a `disc` and its `illuminance`, Rgb lx at normal incidence) of
// E_n · f · max(0, n · s) at a surface of unit normal n, f = fraction(source) in [0, 1] asked
// only of sources above the surface.
template <typename Source, typename Fraction>
Rgb disc_irradiance(std::span<const Source> sources, Vec3 n, const Fraction& fraction) {
  Rgb e;
  for (const Source& s : sources) {
    const double c = dot(n, s.disc.direction);
    if (c <= 0) continue;
    const double f = fraction(s);
    if (f > 0) e += s.illuminance * (f * c);
  }
  return e;
}

// One disc source (a sun, an environment's compact source) as a surface of unit normal n sees
// it (light/seen_light.h): E_n · f · max(0, n · s), in view when that is not 0, and with
// `with_luminance` the disc's luminance (the tint's Y: L · Y(E) / E_n) times f, the mean over
// the whole disc's solid angle.
template <typename Source, typename Fraction>
SeenLight disc_seen_from(const Source& s, Vec3 n, bool with_luminance, const Fraction& fraction) {
  SeenLight out;
  out.direction = s.disc.direction;
  const double c = dot(n, s.disc.direction);
  if (c <= 0) return out;
  const double f = fraction(s);
  if (!(f > 0)) return out;
  out.irradiance = s.illuminance * (f * c);
  out.in_view = true;
  if (with_luminance && s.disc.normal_illuminance > 0) {
    out.luminance = luminance(s.illuminance) * s.disc.luminance / s.disc.normal_illuminance * f;
    out.solid_angle = s.disc.solid_angle;
  }
  return out;
}

// Whether some direction within the disc's cone from `origin` comes within the sphere (centre,
// radius): the sphere not behind the point, and the disc's axis passing its centre within its
// radius plus the cone's spread at that distance (conservative).
bool disc_may_reach(const SunDisc& disc, Vec3 origin, Vec3 centre, double radius);

// The fraction of `disc` for which seen(ω) holds, in [0, 1] (`directions` made from it). Without
// `penumbra`, whether its centre is seen (0 or 1): one direction instead of nine, for the many
// quadrature points of a mean over a surface, where a penumbra's partial values average out.
template <typename Seen>
double disc_fraction(const SunDisc& disc, const DiscDirections& directions, const Seen& seen,
                     bool penumbra = true) {
  const bool centre = seen(disc.direction);
  if (!penumbra) return centre ? 1.0 : 0.0;
  for (std::size_t i = 0; i < kDiscRimDirections; ++i) {
    if (seen(directions.directions[i]) == centre) continue;
    int count = 0;  // the penumbra
    for (std::size_t k = kDiscRimDirections; k < directions.directions.size(); ++k) {
      count += seen(directions.directions[k]) ? 1 : 0;
    }
    return static_cast<double>(count) / kDiscPenumbraDirections;
  }
  return centre ? 1.0 : 0.0;
}

}  // namespace relight
