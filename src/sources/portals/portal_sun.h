// The sun through a window, exact at any point. The shell (sources/portals/shell.h) would put the
// sun's 0.53° disc into one 2.8° cubemap cell and, for the indirect light, into SH of l < 6: at
// receivers the sun patch's edges would smear over about a quarter of a metre. Behind clear glass
// the sun is instead traced from every point that needs it — vertices and sensors when the sun
// moves (sources/portals/portal_lighting.h), pixels in `render --direct pixel` — the way `relight
// reference` traces it (reference/reference_portals.h): a direction of the disc counts when its ray
// from the point leaves the room through this portal (the first glass it crosses is this portal's)
// and meets no opaque surface on the way nor past the window — the room's geometry, overhangs and
// neighbours in `geometry` (the paper's backward occlusion, Yue et al. 2009 §4.1.2), and the
// exterior objects as the state places them.
//
//     E = E_sun,n · tint · f · max(0, n · s),
// f the fraction of the disc seen that way, found by light/disc_visibility.h (9 directions, 80
// in a penumbra). Before any ray, a point from which no direction of the disc comes within the
// portal's bounding sphere gets nothing. Pinned by tests/sources/portals/portal_sun_test.cpp (f at
// and across a window's edge against the closed form) and tests/render/sun_accuracy_test.cpp
// (against the reference).
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "engine/runtime_scene.h"
#include "light/disc_visibility.h"
#include "light/seen_light.h"
#include "light/sky_model.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

struct PortalSun {
  std::uint32_t portal = 0;                   // the portal the sun shines through (scene order)
  SunDisc disc;                               // direction and angular radius
  Rgb illuminance;                            // lx on a plane facing the sun, tint included
  std::shared_ptr<const RayTracer> exterior;  // the exterior objects as placed; null: none
  DiscDirections directions;                  // make_portal_sun fills them
};

PortalSun make_portal_sun(std::uint32_t portal, const SunDisc& disc, Rgb illuminance,
                          std::shared_ptr<const RayTracer> exterior);

// What the sun's rays are traced against.
struct SunGeometry {
  Occluders occluders;                   // the opaque scene (and placed objects)
  const RayTracer& glass;                // the portals' glass, ids: portal index
  std::span<const GlassBounds> portals;  // scene order
};

// The fraction of the sun's disc seen from `origin` (already off the surface) through its
// portal, in [0, 1]. Without `penumbra`, whether the disc's centre is seen (0 or 1): one
// direction instead of nine, for the many quadrature points of a mean over a surface, where
// a penumbra's partial values average out (engine/runtime_scene.h hat_means).
double sun_disc_fraction(const SunGeometry& geometry, const PortalSun& sun, Vec3 origin,
                         bool penumbra = true);

// Σ over `suns` of E_sun,n · f · max(0, n · s) at the surface point p of unit normal n.
Rgb sun_irradiance(const SunGeometry& geometry, std::span<const PortalSun> suns, Vec3 p, Vec3 n,
                   bool penumbra = true);

// `sun` as seen from p (unit normal n): its exact irradiance there (sun_irradiance), and, with
// `with_luminance`, in view when it lights p, its disc's luminance (the tint's Y included)
// times the fraction of the disc seen from p, over the whole disc's solid angle.
SeenLight sun_seen_from(const SunGeometry& geometry, const PortalSun& sun, Vec3 p, Vec3 n,
                        bool with_luminance);

// Whether any of `suns` may light a point of the triangle (a, b, c) of unit normal n: it
// faces the sun, and the sun's cone from some point of it may reach its portal's bounding
// sphere (conservative; engine/runtime_scene.h TriangleFilter).
bool sun_may_light_triangle(const SunGeometry& geometry, std::span<const PortalSun> suns, Vec3 a,
                            Vec3 b, Vec3 c, Vec3 n);

}  // namespace relight
