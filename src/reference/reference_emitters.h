// Near-field emitters in the reference path tracer: each emitter triangle is a
// uniform Lambertian area light of radiance L emitting from its front side. Next-event
// estimation at a surface point x (normal n): one triangle chosen with probability
// P_i ∝ A_i · Y(L_i), a uniform point y on it, and
//     E ≈ L_i · cosθ_x · cosθ_y / |y − x|² · V(x, y) · A_i / P_i,
// V by a shadow ray against the static scene. Emitters are neither occluders nor reflectors
// (docs/scene-format.md, "Emitters"), so continuation rays pass through them and no light is
// counted twice. Independent of the fast path's exact direct (sources/emitters/emitter_direct.h)
// and of its sampling; tests/reference/reference_emitters_test.cpp checks it against the closed
// form of a rectangle.
#pragma once

#include <cstdint>
#include <vector>

#include "light/emitter_placement.h"
#include "math/rgb.h"
#include "math/sampling.h"
#include "reference/reference_weight.h"
#include "trace/ray_tracer.h"

namespace relight {

struct ReferenceEmitters {
  PlacedEmitters placed;
  std::vector<std::uint32_t> triangles;  // the lit triangles
  std::vector<double> cumulative;        // running sums of A_i · Y(L_i) over them
  bool empty() const { return triangles.empty(); }
};

ReferenceEmitters make_reference_emitters(PlacedEmitters placed);

// One-sample estimate of the illuminance (lx per channel) at `origin` (already off the
// surface) on a plane of unit normal n; counts the shadow ray in `rays`. With a glossy
// `weight`, the luminance a glossy surface reflects toward its viewer (f(l, v) per sample:
// continuation rays never meet an emitter, so next-event estimation is the only strategy and
// weighs 1; reference/reference_weight.h).
Rgb emitter_illuminance(const ReferenceEmitters& emitters, const RayTracer& occluders, Vec3 origin,
                        Vec3 n, Pcg32& rng, std::uint64_t& rays,
                        const NextEventWeight& weight = {});

}  // namespace relight
