// Direct light from a luminaire, precomputed as geometry only:
// per receiver the unit direction ω from the luminaire's photometric centre and the
// factor g = V · max(0, n·(−ω)) / d², V the visible fraction of the luminous opening (1 or
// 0 for a point source). At run time E_direct = colour · dimmer · I(ω in the current
// photometric frame) · g, evaluated exactly from the current distribution and aim: no SH
// truncation and no ringing in direct light (going past Dobashi et al. 1995, whose
// direct light is the SH series itself; its mode is kept as "direct": "sh").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/ranks.h"
#include "engine/receivers.h"
#include "light/distribution.h"
#include "light/luminaire_frame.h"
#include "light/photometric_web.h"
#include "light/seen_light.h"
#include "trace/traced_scene.h"

namespace relight {

struct DirectGeometry {
  // Structure of arrays, one entry per receiver.
  std::vector<float> dir_x, dir_y, dir_z;  // unit direction from the luminaire to the receiver
  std::vector<float> factor;               // V · cos θ_receiver / d²  (1/m²)
  std::uint64_t rays = 0;
};

// Points on a luminous opening the precompute traces toward from every receiver (and the run
// time for a luminaire the layout moves or adds, so that both agree).
inline constexpr int kOpeningSamples = 16;

// Points on (or in) the luminous opening, relative to the photometric centre: a
// stratified pattern of about `samples` points over the opening's extent (length along
// C0, width along C90, height along the aim, elliptical in plan for round shapes). A
// point opening or samples <= 1 gives the centre only.
std::vector<Vec3> opening_sample_offsets(const LuminousOpening& opening,
                                         const PhotometricFrame& frame, int samples);

// The luminous opening the transfer uses: the scene's `size` when given, else the
// IES/LDT dimensions (a point for analytic distributions).
LuminousOpening luminaire_opening(const Luminaire& luminaire, const LuminousOpening& from_file);

struct DirectFactor {
  Vec3 direction;     // unit, from the luminaire to the point
  double factor = 0;  // V · cos θ / d² (1/m²)
};

// The direct geometry at one surface point p with unit normal n: what
// compute_direct_geometry stores per receiver, and what a per-pixel renderer evaluates
// at each hit. `rays` counts the shadow rays cast.
DirectFactor direct_factor(const Occluders& occluders, Vec3 p, Vec3 n, Vec3 luminaire_position,
                           const std::vector<Vec3>& opening_offsets, std::uint64_t& rays);

// direct_factor in its two parts, for callers that keep one tracer's visibility and trace
// another's (movable objects, sources/objects/object_lighting.h): the factor is the fraction
// of the opening's points visible times direct_geometry, and a point is visible when every
// tracer leaves it so. OpeningMask: one bit per opening point (at most kMaxOpeningMask).
using OpeningMask = std::array<std::uint64_t, 4>;
inline constexpr std::size_t kMaxOpeningMask = 256;
// cos θ / d² at p (0 where direct_factor is 0 whatever the visibility).
double direct_geometry(Vec3 p, Vec3 n, Vec3 luminaire_position);
// The points among `candidates` that p sees past `occluders`, traced as direct_factor traces
// them. Throws std::invalid_argument for more than kMaxOpeningMask points.
OpeningMask visible_opening_points(const Occluders& occluders, Vec3 p, Vec3 n,
                                   Vec3 luminaire_position,
                                   const std::vector<Vec3>& opening_offsets,
                                   const OpeningMask& candidates, std::uint64_t& rays);
// Every point of an opening of `count` points.
OpeningMask all_opening_points(std::size_t count);
int opening_point_count(const OpeningMask& mask);

// A luminaire as a lighting state sets it, for its exact direct light at any point: at each
// pixel of an image (runtime/direct_light.h) and at the vertices of movable objects
// (sources/objects/object_lighting.h).
struct LuminaireLight {
  Vec3 position;
  PhotometricFrame frame;
  Rgb rgb;  // colour × dimmer (0 when off)
  const Distribution* distribution = nullptr;
  std::vector<Vec3> opening;  // sample offsets on the luminous opening
};

// Luminaire l's irradiance (lux per channel) at a point whose geometry factor toward it is
// `factor` (DirectFactor::factor, V · cos θ / d²) along unit `direction` (from the luminaire
// to the point): colour × dimmer × I(direction) × factor.
inline Rgb luminaire_irradiance(const LuminaireLight& l, Vec3 direction, double factor) {
  return l.rgb * (l.distribution->intensity(l.frame.to_photometric(direction)) * factor);
}

// Direct irradiance (lux per channel) at p with unit normal n from `lights`.
Rgb luminaire_direct_irradiance(const Occluders& occluders, std::span<const LuminaireLight> lights,
                                Vec3 p, Vec3 n);

// A luminous opening projected toward the unit photometric-frame direction u (x along C0, the
// length; y along C90, the width; z along the aim), m²: the bottom face w·l·|cos γ| plus the
// luminous sides h·(w·|sin γ sin C| + l·|sin γ cos C|); round openings π·w·l/4·|cos γ| plus
// a cylinder's (w + l)/2·h·sin γ; 0 for a point.
double projected_opening_area(const LuminousOpening& opening, Vec3 u);

// Luminaire `light` as seen from p (unit normal n): its exact direct irradiance there
// (luminaire_direct_irradiance), and, with `with_luminance`, whether its photometric centre is
// in view (in front of n's plane, unoccluded, shining toward p) with its luminance I/A_p and
// solid angle A_p/r², A_p `opening` (luminaire_opening) projected toward p.
SeenLight luminaire_seen_from(const Occluders& occluders, const LuminaireLight& light,
                              const LuminousOpening& opening, Vec3 p, Vec3 n, bool with_luminance);

// `ray_points` are receiver_ray_points(receivers, mesh): the shadow rays start there, toward the
// luminaire past the static opaque scene `occluders` (the precompute's, or the run time's for a
// luminaire the layout moves or adds). With
// several `ranks` (engine/ranks.h; collective), this process traces its share's rows and keeps
// only those (the others zero): rank 0 gathers them as it writes the file; `rays` counts every
// rank's.
DirectGeometry compute_direct_geometry(const Receivers& receivers,
                                       const std::vector<Vec3>& ray_points,
                                       const RayTracer& occluders, Vec3 luminaire_position,
                                       const std::vector<Vec3>& opening_offsets, bool progress,
                                       const RankShares* ranks = nullptr);

}  // namespace relight
