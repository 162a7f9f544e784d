// The exact direct light of near-field emitters at a point (sensors and pixels get it exactly, as
// luminaires' exact direct; vertices get Sun 2005's SH reconstruction). Each emitter triangle is a
// uniform Lambertian area light of radiance L that emits from its front side. Unoccluded, its
// irradiance on a plane of normal n at p is Lambert's polygon formula over the triangle clipped to
// the plane's upper side,
//     E = L/2 · |Σ_i Θ_i (n · γ_i)|,
// Θ_i the angle subtended by edge i seen from p and γ_i the unit normal of the plane through p
// and that edge — exact. Occlusion by the static scene is the visible fraction of the
// triangle weighted by its unoccluded contribution, w = cosθ_p cosθ_e / d², from a stratified
// set of points on the triangle (shadow rays). Emitters do not hide each other here (as in the
// reference tracer's next-event estimation of emitters). Pinned by
// tests/sources/emitters/emitter_direct_test.cpp (the disc-like closed forms and I/d²).
#pragma once

#include "light/emitter_placement.h"
#include "light/seen_light.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

// Irradiance on the unit-radiance triangle (a, b, c) at p, normal n, emitting toward the side
// its winding faces ((b−a)×(c−a)); 0 behind it. In lx per cd/m².
double triangle_irradiance_factor(Vec3 p, Vec3 n, Vec3 a, Vec3 b, Vec3 c);

// Lx (RGB) at p with unit normal n from every lit emitter; `occluders` may be null (no
// occlusion). `visibility_samples`: points per triangle for its visible fraction (rounded to
// a square, at least 1).
Rgb emitter_direct_irradiance(const PlacedEmitters& emitters, const Occluders* occluders, Vec3 p,
                              Vec3 n, int visibility_samples = 16);

// Emitter k (PlacedEmitters::radiance order) as seen from p (unit normal n): its exact direct
// irradiance there, as emitter_direct_irradiance takes it for its triangles; in view when some
// of it lights p; with `with_luminance` its luminance (the Y of its radiance: an emitter is
// uniform), the solid angle of its triangles that light p, each times its visible fraction,
// and `direction`, their solid-angle-weighted mean (a BRDF sees an emitter as diffuse: the
// per-pixel renderers ask for neither).
SeenLight emitter_seen_from(const PlacedEmitters& emitters, std::size_t k,
                            const Occluders* occluders, Vec3 p, Vec3 n, bool with_luminance,
                            int visibility_samples = 16);

}  // namespace relight
