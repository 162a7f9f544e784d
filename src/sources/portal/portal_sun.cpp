#include "sources/portal/portal_sun.h"

#include <algorithm>
#include <cmath>

#include "math/frame.h"

namespace relight {

namespace {

constexpr int kRimPoints = 8;
constexpr int kSpiralPoints = 64;

// Whether the ray from `origin` along the unit `w` leaves through `sun`'s portal unoccluded.
bool passes(const SunGeometry& g, const PortalSun& sun, Vec3 origin, Vec3 w) {
  const RayHit glass = g.glass.intersect({origin, w});
  if (!glass.hit() || glass.triangle != sun.portal) return false;
  if (g.occluders.occluded({origin, w})) return false;
  return !(sun.exterior && sun.exterior->occluded({origin, w}));
}

// Whether some direction within the disc's cone comes within the portal's bounding sphere.
bool may_reach(const PortalBound& b, const SunDisc& disc, Vec3 origin) {
  const Vec3 v = b.centre - origin;
  const double distance = length(v);
  if (distance <= b.radius) return true;
  const double along = dot(v, disc.direction) / distance;
  const double angle = std::acos(std::clamp(along, -1.0, 1.0));
  return angle <= std::asin(b.radius / distance) + disc.angular_radius + 1e-6;
}

}  // namespace

double sun_disc_fraction(const SunGeometry& g, const PortalSun& sun, Vec3 origin) {
  if (sun.portal >= g.portals.size() || !may_reach(g.portals[sun.portal], sun.disc, origin)) {
    return 0;
  }
  const Frame frame = frame_from_normal(sun.disc.direction);
  const double t = std::tan(sun.disc.angular_radius);
  // A direction of the disc at tangent-plane offset (x, y) · tan r from its centre.
  const auto direction = [&](double x, double y) {
    return normalize(frame.to_world({x * t, y * t, 1}));
  };
  const bool centre = passes(g, sun, origin, sun.disc.direction);
  bool agree = true;
  for (int i = 0; i < kRimPoints && agree; ++i) {
    const double a = 2 * kPi * i / kRimPoints;
    agree = passes(g, sun, origin, direction(std::cos(a), std::sin(a))) == centre;
  }
  if (agree) return centre ? 1.0 : 0.0;
  // The penumbra: a Vogel spiral, equal areas of the disc.
  const double golden = kPi * (3 - std::sqrt(5.0));
  int seen = 0;
  for (int i = 0; i < kSpiralPoints; ++i) {
    const double radius = std::sqrt((i + 0.5) / kSpiralPoints), a = golden * i;
    seen += passes(g, sun, origin, direction(radius * std::cos(a), radius * std::sin(a))) ? 1 : 0;
  }
  return static_cast<double>(seen) / kSpiralPoints;
}

Rgb sun_irradiance(const SunGeometry& g, std::span<const PortalSun> suns, Vec3 p, Vec3 n) {
  Rgb e;
  const Vec3 origin = offset_from_surface(p, n);
  for (const PortalSun& sun : suns) {
    const double c = dot(n, sun.disc.direction);
    if (c <= 0) continue;
    const double f = sun_disc_fraction(g, sun, origin);
    if (f > 0) e += sun.illuminance * (f * c);
  }
  return e;
}

}  // namespace relight
