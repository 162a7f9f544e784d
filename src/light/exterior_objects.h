// Dynamic exterior geometry in a portal's shell (Yue et al. 2009 §3: "Each shell
// acts as an environment light source and its intensity distribution is determined by
// rendering images of the scene, viewed from the center of the shell"; §6: this is what lets
// objects outside the shell move between frames, e.g. a car passing buildings). The exterior
// objects move at every state change, so a small Embree BVH (trace/ray_tracer.h) is rebuilt
// per call and the cubemap is re-rendered by ray casting from the portal centre:
//  * per texel k×k stratified sub-rays through the centres of a k×k grid of equal (s, t)
//    sub-squares of the texel (deterministic); with f the fraction of sub-rays that hit, the
//    texel becomes (1 − f)·(its sun-less environment value) + f·(mean radiance of the hits);
//  * exterior surfaces are two-sided Lambertian of the object's albedo ρ with direct light
//    only (no interreflection among exterior objects, no occlusion of the sky by them):
//      L = ρ/π·(E_sun·max(0, n·s)·V_sun + E_sky(n)),
//    n the geometric face normal turned toward the portal centre, s the sun direction, E_sun
//    the sun's normal illuminance, V_sun ∈ {0, 1} from a shadow ray among the exterior
//    objects, E_sky(n) the Ramamoorthi–Hanrahan irradiance of the environment's continuous
//    part (light/environment_irradiance.h; negative lobes of the 9-term fit clamped at 0);
//  * the sun disc counts in the shell only when the ray from the centre toward it reaches the
//    sky (a neighbouring building shadows the window): sun_visible.
// The environment beyond the objects is assumed infinitely far, as everywhere in the shell.
// Rays go in all directions, including behind the window plane: the shell is the full sphere
// seen from the centre (the transfer ignores directions behind the portal).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "light/environment_irradiance.h"
#include "light/sky_model.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle_soup.h"
#include "trace/ray_tracer.h"

namespace relight {

// Where a portal's shell is centred and which way the exterior lies.
struct PortalFrame {
  Vec3 centre;   // the portal centre, world metres
  Vec3 outward;  // unit normal of the window pointing to the exterior
};

// One piece of exterior geometry in world space (already transformed).
struct ExteriorObject {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;  // indices into positions
  Rgb albedo;                       // diffuse reflectance per channel, ≥ 0
};

// The exterior objects as one BVH, with what shading needs per triangle.
struct ExteriorScene {
  RayTracer tracer;
  std::vector<std::uint32_t> object;  // per triangle (tracer id): index into the objects
  std::vector<Vec3> normal;           // per triangle: unit geometric normal (0 if degenerate)
  std::vector<Rgb> albedo;            // per object
};

// Builds the BVH over all objects. std::invalid_argument for an index out of range, a
// non-finite position or a negative / non-finite albedo.
ExteriorScene build_exterior_scene(std::span<const ExteriorObject> objects);

// Whether the ray from `centre` toward the unit direction `dir` escapes the objects.
bool sun_visible(const ExteriorScene& scene, Vec3 centre, Vec3 dir);

// Radiance leaving an exterior surface hit from `centre` along `dir`, per the model above
// (sun may be null: no sun).
Rgb shade_exterior_hit(const ExteriorScene& scene, const RayHit& hit, Vec3 origin, Vec3 dir,
                       const IrradianceSh& sky_irradiance, const SunDisc* sun);

// Composites the objects into `cubemap` (6·N² texels, math/cubemap.h layout), which holds the
// sun-less environment cubemap on entry, with k×k sub-rays per texel (k ≥ 1) from `centre`.
// Texels no sub-ray hits are left bit-for-bit unchanged. Parallel over texels (oneTBB).
// Returns the number of texels any sub-ray hit.
std::size_t composite_exterior(const ExteriorScene& scene, Vec3 centre, int face_size,
                               int subrays_per_axis, const IrradianceSh& sky_irradiance,
                               const SunDisc* sun, std::span<Rgb> cubemap);

}  // namespace relight
