// The reference tracer's second way to find a point light through a near-mirror (the
// mirror limit; material/mirror_planes.h). A backward path tracer finds the light a
// polished floor throws on the ceiling only when a ceiling point's cosine-distributed ray
// lands where the floor's narrow lobe points at the light — for roughness 0.05 a spot of
// millimetres: almost never, and then with an enormous weight. So at a Lambertian point x,
// for each luminaire at p and each near-mirror plane in front of which both lie, a direction
// is also drawn about the image's direction d0 = (p' − x)/|p' − x| (p' = p mirrored in the
// plane): d0 tilted by a slope s in the plane normal to d0, s drawn from the GGX slope
// distribution (a two-dimensional Student t, Walter et al. 2007, "Microfacet Models for
// Refraction through Rough Surfaces", Eq. 33 in slope form) of width
//     β = 2 α s_light / (s_x + s_light)      (the lobe's half-vector width α seen from x:
//                                             moving y on the plane by δ turns x's direction
//                                             by δ/s_x and the half vector by half of
//                                             δ/s_x + δ/s_light),
// s_x = |x − y0|, s_light = |y0 − p|, y0 where x–p' crosses the plane; density per steradian
//     q(ω) = p_s(s) / cos³ φ,  p_s(s) = 1 / (π β² (1 + |s|²/β²)²),  φ the angle from d0.
// The sun (parallel light) likewise, about its mirrored direction with width 2α plus the disc's
// angular radius. Where that ray meets the plane's triangles at y, the light the mirror
// reflects toward x is
// f(l_y, −ω) I cos θ_y / |p − y|² by next-event estimation at y; x counts it with cos θ_x / q
// and the power heuristic against the cosine sampling that continues the path (Veach 1997
// §9.2.4), whose own next event at y takes the complementary weight
// (reference/reference_tracer.cpp). Unbiased for any plane and roughness; it only makes the
// estimate converge. Pinned by tests/reference/reference_mirror_test.cpp and the mirror-limit
// test against the image-source closed form (tests/cli/mirror_limit_test.cpp).
#pragma once

#include <optional>

#include "material/mirror_planes.h"
#include "math/vec3.h"

namespace relight {

struct MirrorLobe {
  Vec3 axis, t1, t2;  // d0 and two unit vectors normal to it
  double width = 0;   // β
};

// The lobe about the image of a light at `light` in `plane` (material roughness α² = alpha)
// seen from x; none unless x and the light both lie in front of the plane.
std::optional<MirrorLobe> mirror_lobe(const MirrorPlane& plane, double alpha, Vec3 x, Vec3 light);

// The lobe about the sun's image in `plane` seen from x (the sun toward unit `toward`, of
// angular radius `radius`): axis the mirrored direction, width 2α + radius (parallel light: y
// moving turns only x's direction, the half vector by half as much); none unless x lies in
// front of the plane and the sun above it.
std::optional<MirrorLobe> mirror_sun_lobe(const MirrorPlane& plane, double alpha, Vec3 x,
                                          Vec3 toward, double radius);

// A direction drawn from the lobe with two uniform numbers in [0, 1).
Vec3 sample_mirror_lobe(const MirrorLobe& lobe, double u1, double u2);

// The density (per steradian) with which sample_mirror_lobe draws unit direction w.
double mirror_lobe_pdf(const MirrorLobe& lobe, Vec3 w);

}  // namespace relight
