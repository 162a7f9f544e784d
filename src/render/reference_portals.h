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

#include <cstdint>
#include <string>
#include <vector>

#include "light/environment.h"
#include "math/rgb.h"
#include "math/sampling.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "trace/traced_scene.h"

namespace relight {

struct ReferencePortal {
  std::string name;
  Environment environment;
  Rgb tint{1, 1, 1};                     // the glass's transmittance per channel
  std::vector<std::uint32_t> triangles;  // prepared-mesh triangle ids
  std::vector<double> cumulative_area;   // running sums of the triangles' areas, m²
  double area() const { return cumulative_area.empty() ? 0.0 : cumulative_area.back(); }
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
ReferencePortals make_reference_portals(const Scene& scene, const PreparedMesh& mesh,
                                        std::vector<Environment> environments);

// What the tracer needs to look at the exterior.
struct ExteriorView {
  const PreparedMesh& mesh;
  const TracedScene& traced;
  const ReferencePortals& portals;
};

// The portal through which `ray` leaves the scene: the first portal triangle along it when
// no opaque surface lies anywhere on it; kNoPortal otherwise. Counts the rays it casts.
std::int32_t escape_portal(const ExteriorView& view, const Ray& ray, std::uint64_t& rays);

// Illuminance (lux per channel) at `origin` (already off the surface) on a plane of unit
// normal n from the environments seen through the portals: per portal one area sample of
// the continuous environment and, for a sky with a sun, one sun-cone sample (see above).
Rgb portal_illuminance(const ExteriorView& view, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays);

}  // namespace relight
