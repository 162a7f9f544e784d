// The exterior seen through a portal: an evaluable environment built from an EnvironmentSpec, its
// SH projection and its cubemap rasterisation, in absolute units (cd/m² per linear Rec.709 channel,
// the photometric quantity their Y). World frame: right-handed, y up, NORTH −z, EAST +x; SH in the
// world frame of math/sh.h (polar axis = world z); cubemaps in the layout of math/cubemap.h.
//
// Kinds:
//  * uniform — one radiance over the whole sphere.
//  * map — a piecewise-constant equirectangular image (math/equirect.h orientation: u = 0 north,
//    u = ¼ east, top row = zenith), each texel constant over its exact cell, times `scale`,
//    turned by `rotate_deg` clockwise seen from above (a feature at azimuth A moves to
//    A + rotate_deg). Lookups take the texel containing the direction (no filtering), so every
//    integral of the environment equals the texel sum Σ L·Ω.
//  * sky — light/sky_model.h: CIE sky dome, Lambertian ground, optional sun disc; grey
//    (r = g = b = luminance).
//
// Projections (each is the integral of the environment against a basis, with the sun disc
// done in closed form):
//  * environment_sh: c_lm = ∫ L(ω) Y_lm(ω) dω, l < order.
//      uniform: exactly c_00 = sqrt(4π)·L, the rest 0.
//      map: Σ_texels L·Y_lm(texel centre)·Ω_texel (error O(1/H²) for smooth content), i.e.
//           a quadrature at the map's own resolution.
//      sky: the dome by sky_dome_quadrature (light/sky_model.h: Gauss–Legendre in zenith angle
//           split at the sun, Gauss–Legendre in azimuth per half turn from the sun's meridian;
//           max(64, order + 32) × max(128, 2·order + 64) nodes), so the horizon and the
//           circumsolar cusp lie on panel edges; the uniform ground and the uniform sun disc
//           exactly, as spherical caps, by the Funk–Hecke formula: a cap of luminance L and
//           angular radius ρ about the axis a has
//             c_lm = L·2π·∫_{cos ρ}^{1} P_l(t) dt · Y_lm(a),
//             ∫_{cos ρ}^{1} P_l = (P_{l−1}(cos ρ) − P_{l+1}(cos ρ))/(2l+1) (l ≥ 1), 1 − cos ρ (l =
//             0).
//           For the sun this is the delta E·Y_lm(s), E = ∫_disc L dω, times a band factor
//           ≈ 1 − l(l+1)ρ²/8 (0.9973 at l = 31, 0.989 at l = 63), so the clamped-cosine
//           irradiance of the SH tends to the exact normal illuminance of the disc.
//  * environment_cubemap: per-texel average radiance (1/Ω_texel)∫_texel L dω.
//      uniform: exact.
//      sky: k×k midpoint sub-cells of exact solid angle per texel, k = max(4, ⌈64/N⌉), texel
//           rows split at the horizon (for even N it already lies on texel edges); the sun
//           disc's ∫ L dω is deposited into the texel containing its centre, so Σ L·Ω over the
//           texels keeps the sun's energy exactly.
//      map: exact (up to a 3-point Gauss–Legendre rule on smooth pieces of the texel edges)
//           by Green's theorem in the map's equal-area (φ, cos θ) plane, see
//           light/environment_map_cubemap.h: a constant map gives a constant cubemap and
//           Σ L·Ω over the cube equals Σ L·Ω over the map to rounding.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "light/sky_model.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/environment_spec.h"

namespace relight {

// An equirectangular RGB image: row-major, top row (zenith) first, values in cd/m² (before the
// environment's scale).
struct EquirectMap {
  int width = 0, height = 0;
  std::vector<Rgb> texels;
};

// Compass rotation of a map: a map direction at azimuth A is seen at A + rotate_deg.
struct MapRotation {
  double c = 1, s = 0;
  explicit MapRotation(double rotate_deg)
      : c(std::cos(rotate_deg * (kPi / 180))), s(std::sin(rotate_deg * (kPi / 180))) {}
  // World → map frame (azimuth − rotate_deg).
  Vec3 to_map(Vec3 d) const { return {d.x * c + d.z * s, d.y, d.z * c - d.x * s}; }
  // Map → world frame (azimuth + rotate_deg).
  Vec3 to_world(Vec3 d) const { return {d.x * c - d.z * s, d.y, d.z * c + d.x * s}; }
};

enum class EnvironmentKind { kUniform, kMap, kSky };

struct Environment {
  EnvironmentKind kind = EnvironmentKind::kUniform;
  Rgb uniform_radiance;                    // kUniform
  std::shared_ptr<const EquirectMap> map;  // kMap
  double rotate_deg = 0;                   // kMap: clockwise seen from above
  double scale = 1;                        // kMap: multiplies the texels
  SkyModel sky;                            // kSky

  // Radiance (cd/m² per channel) arriving from the unit world direction `dir` (the direction
  // looked in), including the sun disc.
  Rgb radiance(Vec3 dir) const;
  // The same without the sun disc: the continuous part.
  Rgb diffuse_radiance(Vec3 dir) const;
  // The sun disc of a sky whose sun is above the horizon and bright (else nullopt). Maps carry
  // their sun, if any, in the texels.
  const std::optional<SunDisc>& sun() const;
};

Environment make_uniform_environment(Rgb radiance);
// Throws std::invalid_argument when the map is null, empty or its texel count is not
// width·height, or scale < 0.
Environment make_map_environment(std::shared_ptr<const EquirectMap> map, double rotate_deg,
                                 double scale);
Environment make_sky_environment(SkyModel sky);

// Unit world direction toward the sun of a spec: PSA (light/sun_position.h) from place and
// local time, or the given angles; its compass azimuth turned by the site's north_deg
// (clockwise seen from above). Throws std::invalid_argument for SunPlacement::kNone.
Vec3 sun_direction(const SunSpec& sun, double north_deg = 0);
// The day of the year of a sun by place and time, 0 (no date) otherwise.
int sun_day_of_year(const SunSpec& sun);

// The environment of a spec. A map spec needs the loaded image (light/environment_map_io.h
// reads spec.file); other kinds ignore `map`. A sky without a "sun" puts the (irrelevant) sun
// at the zenith; a cie_sky without a brightness takes it from light/daylight_availability.h.
// Maps and suns are turned by the spec's north_deg.
Environment make_environment(const EnvironmentSpec& spec,
                             std::shared_ptr<const EquirectMap> map = nullptr);

// SH coefficients c_lm = ∫ L Y_lm dω, l < order (order >= 1), per channel. See above.
std::vector<Rgb> environment_sh(const Environment& env, int order);

// 6·N² per-texel average radiances in the math/cubemap.h layout (N = face_size >= 1).
std::vector<Rgb> environment_cubemap(const Environment& env, int face_size);

// ∫ L dω over the sphere (sun disc included): Σ L·Ω of the map texels, 4πL for a uniform
// environment, a fine quadrature for a sky. For checks and reports.
Rgb environment_integral(const Environment& env);

}  // namespace relight
