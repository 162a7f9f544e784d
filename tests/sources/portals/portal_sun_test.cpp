// sources/portals/portal_sun.h: the fraction of the sun's disc seen through a window, against
// the closed form of a disc cut by the window's straight edge, and the rules for which
// rays count (their own portal first, nothing opaque, no exterior object).
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sources/portals/portal_sun.h"

namespace relight {
namespace {

// A 2 × 2 m window in the plane z = 0 about `centre`, as RuntimeScene bounds it.
GlassBounds window_bounds(Vec3 centre) {
  GlassBounds b;
  b.sphere = {centre, std::sqrt(2.0)};
  b.normal = {0, 0, 1};
  b.u = {1, 0, 0};
  b.v = {0, 1, 0};
  b.u_min = b.v_min = -1;
  b.u_max = b.v_max = 1;
  return b;
}

// Two 2 × 2 m windows in the plane z = 0 (x ∈ [−1, 1] and, portal 1, x ∈ [3, 5]; y ∈ [−1, 1])
// and the sun straight along +z; points at z = −1.
struct Windows {
  std::vector<Vec3> positions{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
                              {3, -1, 0},  {5, -1, 0}, {5, 1, 0}, {3, 1, 0}};
  RayTracer glass{positions, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, {0, 0, 1, 1}};
  RayTracer nothing{positions, {}, {}};
  std::vector<GlassBounds> bounds{window_bounds({0, 0, 0}), window_bounds({4, 0, 0})};
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
// its mirror for h < 0. The penumbra's 80 directions resolve f within 0.045 for any offset and
// direction of a straight edge, and exactly half at h = 0 (light/disc_visibility.h).
TEST(PortalSun, APenumbraSeesTheDiscCutByTheEdgeWithinFivePercent) {
  const Windows w;
  const double r = footprint(w.sun);
  for (const double h : {-0.8, -0.5, -0.2, 0.0, 0.2, 0.5, 0.8}) {
    const double segment = (std::acos(std::abs(h)) - std::abs(h) * std::sqrt(1 - h * h)) / kPi;
    const double expected = h >= 0 ? 1 - segment : segment;
    const double f = sun_disc_fraction(w.geometry(w.nothing), w.sun, {1 - h * r, 0, -1});
    std::printf("centre %+.1f R inside the edge: f = %.4f, closed form %.4f\n", h, f, expected);
    EXPECT_NEAR(f, expected, 0.045) << h;
    if (h == 0.0) {
      EXPECT_EQ(f, 0.5);  // the penumbra's pairs straddle an edge through the disc's centre
    }
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

// sun_may_light_triangle culls the room's triangles for the sun's patch (every hour of `relight
// annual`): by the glass's bounding sphere and by its rectangle, the triangle moved along the
// sun onto the window's plane. Conservative: no triangle that some point of it sees any of the
// disc through a window of (4 × 4 points and the corners, penumbra traced) is culled, over
// random small triangles up to 2 m behind the windows and suns up to 60° from the normal —
// and the rectangle culls triangles the sphere alone keeps.
TEST(PortalSun, TrianglesCulledForTheSunPatchSeeNoneOfTheSun) {
  const Windows w;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0, 1);
  int culled = 0, lit = 0, kept_by_sphere_alone = 0;
  for (int k = 0; k < 8000; ++k) {
    const double polar = radians(60 * unit(rng)), azimuth = 2 * kPi * unit(rng);
    const Vec3 s{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                 std::cos(polar)};
    const PortalSun sun = make_portal_sun(k % 2, make_sun_disc(s, 100000), {1, 1, 1}, nullptr);
    const Vec3 a{-2.5 + 9 * unit(rng), -2.5 + 5 * unit(rng), -0.01 - 2 * unit(rng)};
    const double size = 0.02 + 0.3 * unit(rng);
    const Vec3 b = a + Vec3{size * (unit(rng) - 0.5), size * (unit(rng) - 0.5), 0.1 * size};
    const Vec3 c = a + Vec3{size * (unit(rng) - 0.5), size * (unit(rng) - 0.5), -0.1 * size};
    const Vec3 n = Vec3{0, 0, 1};  // faces the window; the normal only gates facing the sun
    const SunGeometry g = w.geometry(w.nothing);
    bool sees = false;
    for (int i = 0; i <= 4 && !sees; ++i) {
      for (int j = 0; i + j <= 4 && !sees; ++j) {
        const Vec3 p = a + (b - a) * (i / 4.0) + (c - a) * (j / 4.0);
        sees = sun_disc_fraction(g, sun, offset_from_surface(p, n), true) > 0;
      }
    }
    const bool may = sun_may_light_triangle(g, std::span(&sun, 1), a, b, c, n);
    if (sees) {
      ++lit;
      EXPECT_TRUE(may) << "triangle " << k;
    }
    if (!may) {
      ++culled;
      // What the sphere alone (RuntimeScene's bound before the rectangle) would have kept.
      GlassBounds sphere_only = w.bounds[sun.portal];
      sphere_only.u_min = sphere_only.v_min = -1e9;
      sphere_only.u_max = sphere_only.v_max = 1e9;
      std::vector<GlassBounds> loose = w.bounds;
      loose[sun.portal] = sphere_only;
      const SunGeometry g_loose{w.nothing, w.glass, loose};
      if (sun_may_light_triangle(g_loose, std::span(&sun, 1), a, b, c, n)) ++kept_by_sphere_alone;
    }
  }
  std::printf("%d triangles lit, %d culled, %d of them kept by the sphere alone\n", lit, culled,
              kept_by_sphere_alone);
  EXPECT_GT(lit, 500);
  EXPECT_GT(culled, 2000);
  EXPECT_GT(kept_by_sphere_alone, 400);
}

}  // namespace
}  // namespace relight
