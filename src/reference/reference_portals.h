// Daylight in the reference path tracer: the exterior seen through portals (windows).
//
// Yue et al. 2009 (§3) lets the environment reach an interior only through its window
// openings. The reference follows that literally, with no shared code from the transfer
// side: a ray that crosses a triangle of portal p and then meets no opaque surface
// receives p's environment radiance in its direction; a ray that escapes without crossing
// a portal receives nothing. When a ray crosses several portal triangles the first one
// (the one nearest the interior) decides whose environment it sees.
//
// Estimators at a point x with unit normal n (both unbiased; together they count every
// direction that escapes through a portal exactly once, so cosine continuation rays that
// escape add nothing):
//  * the continuous environment (Environment::diffuse_radiance, without the sun disc), by
//    next-event estimation over the portal's area: y uniform on the portal's triangles
//    (triangle chosen in proportion to its area, pdf 1/A),
//      E ≈ L(ω)·cos θ_x·|cos θ_y| / |y − x|² · A,   ω = (y − x)/|y − x|,
//    counted when x sees y with no opaque surface and no nearer portal triangle between,
//    and the continuation from y along ω reaches the exterior (backward occlusion: an
//    overhang or a neighbouring building outside the window casts its shadow);
//  * the sun disc of a sky (Environment::sun()), by a direction ω uniform in the disc's
//    cone (pdf 1/Ω_sun): E ≈ L_sun·Ω_sun·cos θ_x when the ray from x leaves through
//    this portal. Since ∫_disc ω dω = s·π sin²r, the mean is L_sun·π sin²r·cos θ_s =
//    E_sun,n·cos θ_s exactly (light/sky_model.h). Each sample averages ω with its mirror
//    image about the disc's axis (antithetic variates), which cancels the spread of cos θ_x
//    across the disc, the only noise of a sunlit point.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "light/environment.h"
#include "light/exterior_objects.h"
#include "math/glazing.h"
#include "math/rgb.h"
#include "math/sampling.h"
#include "reference/reference_weight.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "trace/ray_tracer.h"
#include "trace/traced_scene.h"

namespace relight {

// The exterior objects in front of one portal as a state places them. The reference lights
// them as the shell's model does (light/exterior_objects.h: two-sided Lambertian,
// direct light only) but without its approximations: at the true point the light ray meets,
// the sun with shadows among the objects, and the environment's continuous part by one cosine
// sample, occluded by the objects.
struct ReferenceExterior {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Rgb> albedo;  // per triangle
  RayTracer tracer;         // ids: triangle index
};

// Frosted glass as the reference sees it: the shell's flux-preserving von Mises–Fisher
// scattering (sources/portals/shell_frost.h) taken continuously. Light arriving from ω in front
// of the window (c(ω) = ω·outward > 0) leaves toward ω' with weight K(ω, ω')·c(ω')/Z(ω),
// K = exp((ω·ω' − 1)/σ²), σ = frost_deg, Z(ω) = ∫_{c>0} K(ω, ω'')·c(ω'') dω'', so that
//     L'(ω') = ∫_{c>0} L(ω)·c(ω)·K(ω, ω')/Z(ω) dω.
// One sample: ω drawn from K(·, ω') (a von Mises–Fisher distribution, normaliser C), L'(ω') ≈
// L(ω)·c(ω)·C/Z(ω); the sun's share is taken exactly, E_disc·c(s)·K(s, ω')/Z(s). Z depends
// only on c(ω): a table of 257 values over c ∈ [0, 1].
struct ReferenceFrost {
  double sigma = 0;              // radians
  std::vector<double> z_of_cos;  // Z at c = i / 256
  double normaliser = 0;         // C = ∫_sphere K dω = 2πσ²(1 − exp(−2/σ²))
};

struct ReferencePortal {
  std::string name;
  Environment environment;
  Rgb tint{1, 1, 1};                                  // the glass's transmittance per channel
  Vec3 outward{0, 0, 1};                              // unit, from the room toward the environment
  std::shared_ptr<const ReferenceFrost> frost;        // null: clear glass
  std::optional<Glazing> glazing;                     // none: an opening (math/glazing.h)
  std::shared_ptr<const ReferenceExterior> exterior;  // null: none in front of it
  std::vector<std::uint32_t> triangles;               // prepared-mesh triangle ids
  std::vector<double> cumulative_area;                // running sums of the triangles' areas, m²
  double area() const { return cumulative_area.empty() ? 0.0 : cumulative_area.back(); }
  // Frosted or diffusing glass spreads the sun: it is no sun disc seen through it.
  bool spreads_sun() const { return frost || (glazing && glazing->diffusing); }
  // The glazing's transmittance for light arriving along `dir` (outward); 1 without glazing.
  double transmittance(Vec3 dir) const {
    return glazing ? glazing_transmittance(*glazing, dot(dir, outward)) : 1.0;
  }
};

inline constexpr std::int32_t kNoPortal = -1;

struct ReferencePortals {
  std::vector<ReferencePortal> portals;       // scene order
  std::vector<std::int32_t> triangle_portal;  // per prepared triangle: portal index or kNoPortal
};

// The portals of `scene` over the prepared mesh, each with its environment
// (`environments[i]` for scene.portals[i]; light/environment_map_io.h's load_environment
// reads map files, tests pass environments directly). Portal triangles of a material that
// no portal names stay openings to a black exterior. Throws std::invalid_argument when
// the counts differ.
// `exterior[i]`: the exterior objects placed for scene.portals[i] (empty: none).
ReferencePortals make_reference_portals(
    const Scene& scene, const PreparedMesh& mesh, std::vector<Environment> environments,
    const std::vector<std::vector<ExteriorObject>>& exterior = {});

// The luminance that reaches the room through the portal's glass looking along `dir` (outward):
// the exterior object or environment seen, times the glazing's transmittance at the direction
// it arrives from, through frost when the glass is frosted, tinted; the sun disc only when
// `with_sun` (area samples leave it to the sun-cone samples of clear glass; frosted and
// diffusing glass spread it, and it is included here). Diffusing glass shows the same luminance
// every way, (1/π)·∫ L·T·cos dω over the directions in front: one cosine-distributed sample,
// the sun's share exactly.
Rgb through_glass(const ReferencePortal& portal, Vec3 from, Vec3 dir, bool with_sun, Pcg32& rng,
                  std::uint64_t& rays);

// The luminance leaving the first exterior object along `ray` (which starts outside the
// window) back toward its origin, or nothing when the ray reaches the environment.
std::optional<Rgb> exterior_radiance(const ReferencePortal& portal, const Ray& ray, Pcg32& rng,
                                     std::uint64_t& rays);

// What the tracer needs to look at the exterior.
struct ExteriorView {
  const PreparedMesh& mesh;
  const TracedScene& traced;
  const ReferencePortals& portals;
};

// The portal through which `ray` leaves the scene: the first portal triangle along it when
// no opaque surface lies anywhere on it; kNoPortal otherwise. Counts the rays it casts.
std::int32_t escape_portal(const ExteriorView& view, const Ray& ray, std::uint64_t& rays);

// Two directions in the cone of the sun disc, each uniform in it (pdf 1 / solid_angle) and
// mirror images of each other about its axis (antithetic: their cosines to any normal sum to
// 2·cos α·cos θ_s, so the pair's estimate hardly varies where both are unoccluded). The
// portals' sun samples and the top-level environment's (reference_tracer.cpp) use it.
std::array<Vec3, 2> sample_sun_directions(const SunDisc& sun, Pcg32& rng);

// Illuminance (lux per channel) at `origin` (already off the surface) on a plane of unit
// normal n from the environments seen through the portals: per portal one area sample of
// the continuous environment and, for a sky with a sun, one sun-cone sample (see above).
// With a glossy `weight`, the luminance a glossy surface reflects toward its viewer from
// them, each sample weighted against BRDF sampling (reference/reference_weight.h).
// With `sun_weight`, each portal's sun-cone sample is weighted by sun_weight(portal) too (a
// second strategy found the same light: reference/reference_mirror.h).
Rgb portal_illuminance(const ExteriorView& view, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays, const NextEventWeight& weight = {},
                       const std::function<double(std::size_t)>& sun_weight = {});

// Portal p's sun-cone sample alone (nothing for a portal without a sun or with frosted glass).
Rgb portal_sun_illuminance(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
                           std::uint64_t& rays, const NextEventWeight& weight = {});

// What a continuation ray drawn by BRDF sampling with density `brdf_pdf` (from a glossy
// surface) receives from the exterior when it leaves through a portal: the glass's
// luminance times the BRDF strategy's weight against the area sample of that portal, and the
// sun disc's (clear glass) against the sun-cone sample (reference/reference_weight.h); nothing
// when it meets an opaque surface or leaves through no portal.
// With `sun_weight`, the sun disc's part is weighted by sun_weight(portal) too.
Rgb escaped_radiance(const ExteriorView& view, const Ray& ray, double brdf_pdf, Pcg32& rng,
                     std::uint64_t& rays,
                     const std::function<double(std::size_t)>& sun_weight = {});

}  // namespace relight
