// sources/portal/portal_sun.h: the fraction of the sun's disc seen through a window, against
// the closed form of a disc cut by the window's straight edge, and the rules for which
// rays count (their own portal first, nothing opaque, no exterior object).
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "sources/portal/portal_sun.h"

namespace relight {
namespace {

// Two 2 × 2 m windows in the plane z = 0 (x ∈ [−1, 1] and, portal 1, x ∈ [3, 5]; y ∈ [−1, 1])
// and the sun straight along +z; points at z = −1.
struct Windows {
  std::vector<Vec3> positions{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
                              {3, -1, 0},  {5, -1, 0}, {5, 1, 0}, {3, 1, 0}};
  RayTracer glass{positions, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, {0, 0, 1, 1}};
  RayTracer nothing{positions, {}, {}};
  std::vector<BoundingSphere> bounds{{{0, 0, 0}, 2 * std::sqrt(2.0)},
                                     {{4, 0, 0}, 2 * std::sqrt(2.0)}};
  PortalSun sun =
      make_portal_sun(0, make_sun_disc({0, 0, 1}, 100000), {100000, 100000, 100000}, nullptr);
  SunGeometry geometry(const RayTracer& occluders) const { return {occluders, glass, bounds}; }
};

// The footprint of the disc on the window from 1 m: tan(0.265°) m.
double footprint(const PortalSun& sun) {
  return std::tan(sun.disc.angular_radius);
}

TEST(PortalSun, ADiscWhollyInsideTheWindowIsWholeAndGivesTheClosedForm) {
  const Windows w;
  EXPECT_EQ(sun_disc_fraction(w.geometry(w.nothing), w.sun, {0, 0, -1}), 1.0);
  const Rgb e = sun_irradiance(w.geometry(w.nothing), std::span(&w.sun, 1), {0.2, 0.3, -1},
                               normalize(Vec3{0, 0.6, 0.8}));
  EXPECT_NEAR(e.r, 100000 * 0.8, 1e-6 * 100000);
  EXPECT_EQ(sun_disc_fraction(w.geometry(w.nothing), w.sun, {2, 0, -1}), 0.0);  // between them
}

// The window's edge x = 1 at distance h·R from the disc's centre (R its footprint): the visible
// part is the disc minus a circular segment, f = 1 − (acos h − h√(1 − h²))/π for h ≥ 0, and
// its mirror for h < 0. The 64 spiral points resolve f within 0.047 for any offset and
// direction of a straight edge (portal_sun.h).
TEST(PortalSun, APenumbraSeesTheDiscCutByTheEdgeWithinFivePercent) {
  const Windows w;
  const double r = footprint(w.sun);
  for (const double h : {-0.8, -0.5, -0.2, 0.0, 0.2, 0.5, 0.8}) {
    const double segment = (std::acos(std::abs(h)) - std::abs(h) * std::sqrt(1 - h * h)) / kPi;
    const double expected = h >= 0 ? 1 - segment : segment;
    const double f = sun_disc_fraction(w.geometry(w.nothing), w.sun, {1 - h * r, 0, -1});
    std::printf("centre %+.1f R inside the edge: f = %.4f, closed form %.4f\n", h, f, expected);
    EXPECT_NEAR(f, expected, 0.047) << h;
  }
}

TEST(PortalSun, OnlyRaysLeavingThroughTheirOwnPortalUnoccludedCount) {
  Windows w;
  // Through portal 1, the sun of portal 0 does not count.
  EXPECT_EQ(sun_disc_fraction(w.geometry(w.nothing), w.sun, {4, 0, -1}), 0.0);
  // An opaque plate past the window (the backward occlusion) or before it.
  const RayTracer past(w.positions, {{0, 1, 2}}, {0});  // the window's own triangle, opaque
  std::vector<Vec3> plate{{-2, -2, 0.5}, {2, -2, 0.5}, {2, 2, 0.5}, {-2, 2, 0.5}};
  const RayTracer beyond(plate, {{0, 1, 2}, {0, 2, 3}}, {0, 1});
  EXPECT_EQ(sun_disc_fraction(w.geometry(beyond), w.sun, {0, 0, -1}), 0.0);
  // An exterior object in front of the window.
  PortalSun shaded = w.sun;
  shaded.exterior = std::make_shared<const RayTracer>(
      plate, std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}, std::vector<std::uint32_t>{0, 1});
  EXPECT_EQ(sun_disc_fraction(w.geometry(w.nothing), shaded, {0, 0, -1}), 0.0);
  // Facing away from the sun: nothing, whatever is seen.
  const Rgb e = sun_irradiance(w.geometry(w.nothing), std::span(&w.sun, 1), {0, 0, -1}, {0, 0, -1});
  EXPECT_EQ(e.r, 0.0);
}

}  // namespace
}  // namespace relight
