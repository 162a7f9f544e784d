#include "sources/portals/portal_sun.h"

#include <algorithm>
#include <cmath>

namespace relight {

namespace {

// Whether the ray from `origin` along the unit `w` leaves through `sun`'s portal unoccluded.
bool passes(const SunGeometry& g, const PortalSun& sun, Vec3 origin, Vec3 w) {
  const RayHit glass = g.glass.intersect({origin, w});
  if (!glass.hit() || glass.triangle != sun.portal) return false;
  if (g.occluders.occluded({origin, w})) return false;
  return !(sun.exterior && sun.exterior->occluded({origin, w}));
}

bool may_reach(const BoundingSphere& b, const SunDisc& disc, Vec3 origin) {
  return disc_may_reach(disc, origin, b.centre, b.radius);
}

// Whether a ray of the disc's cone from some point of the triangle (a, b, c) may cross the
// glass's slab within its rectangle (GlassBounds): the triangle moved along the sun's axis
// onto the plane is a triangle again (a parallel projection), whose box there must meet the
// rectangle grown by what the other rays of the cone add and by the offset of ray origins
// from surfaces. A ray at angle ε ≤ r from the axis s, from a point at distance t along s from
// the plane, crosses it within 2·t·tan r / (|s·n| − tan r) of the axis's crossing, and a
// glass vertex at distance depth from the plane moves a crossing by at most
// depth / (|s·n| − tan r). Conservative: true whenever a corner is not in front of the plane
// or the sun grazes it (|s·n| < 0.05).
bool may_cross_glass(const GlassBounds& g, Vec3 s, double tan_spread, const Vec3 (&corners)[3]) {
  const double cos_incidence = std::abs(dot(s, g.normal));
  if (cos_incidence < 0.05 || cos_incidence <= 2 * tan_spread) return true;
  double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300, t_max = 0, scale = 1;
  for (const Vec3& p : corners) {
    const double t = dot(g.sphere.centre - p, g.normal) / dot(s, g.normal);
    if (!(t > 0)) return true;
    t_max = std::max(t_max, t);
    const Vec3 q = p + s * t - g.sphere.centre;
    u_lo = std::min(u_lo, dot(q, g.u));
    u_hi = std::max(u_hi, dot(q, g.u));
    v_lo = std::min(v_lo, dot(q, g.v));
    v_hi = std::max(v_hi, dot(q, g.v));
    scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const double margin =
      (2.02 * t_max * tan_spread + g.depth) / (cos_incidence - tan_spread) + 1e-4 * scale;
  return u_hi >= g.u_min - margin && u_lo <= g.u_max + margin && v_hi >= g.v_min - margin &&
         v_lo <= g.v_max + margin;
}

}  // namespace

PortalSun make_portal_sun(std::uint32_t portal, const SunDisc& disc, Rgb illuminance,
                          std::shared_ptr<const RayTracer> exterior) {
  return {portal, disc, illuminance, std::move(exterior), disc_directions(disc)};
}

double sun_disc_fraction(const SunGeometry& g, const PortalSun& sun, Vec3 origin, bool penumbra) {
  if (sun.portal >= g.portals.size() ||
      !may_reach(g.portals[sun.portal].sphere, sun.disc, origin)) {
    return 0;
  }
  return disc_fraction(
      sun.disc, sun.directions, [&](Vec3 w) { return passes(g, sun, origin, w); }, penumbra);
}

Rgb sun_irradiance(const SunGeometry& g, std::span<const PortalSun> suns, Vec3 p, Vec3 n,
                   bool penumbra) {
  const Vec3 origin = offset_from_surface(p, n);
  return disc_irradiance(
      suns, n, [&](const PortalSun& sun) { return sun_disc_fraction(g, sun, origin, penumbra); });
}

SeenLight sun_seen_from(const SunGeometry& g, const PortalSun& sun, Vec3 p, Vec3 n,
                        bool with_luminance) {
  const Vec3 origin = offset_from_surface(p, n);
  return disc_seen_from(sun, n, with_luminance,
                        [&](const PortalSun& s) { return sun_disc_fraction(g, s, origin); });
}

bool sun_may_light_triangle(const SunGeometry& g, std::span<const PortalSun> suns, Vec3 a, Vec3 b,
                            Vec3 c, Vec3 n) {
  // The bounding sphere only for a triangle that faces some sun (every hour of `relight
  // annual` asks this of every triangle of the room).
  Vec3 m;
  double r = -1;
  for (const PortalSun& sun : suns) {
    if (sun.portal >= g.portals.size() || dot(n, sun.disc.direction) <= 0) continue;
    if (r < 0) {
      m = (a + b + c) / 3;
      r = std::max({length(a - m), length(b - m), length(c - m)});
    }
    // A ray from a point within r of m is a ray from m moved by at most r.
    const GlassBounds& bound = g.portals[sun.portal];
    if (may_reach({bound.sphere.centre, bound.sphere.radius + 1.01 * r}, sun.disc, m) &&
        may_cross_glass(bound, sun.disc.direction, sun.disc.tan_angular_radius, {a, b, c})) {
      return true;
    }
  }
  return false;
}

}  // namespace relight
