// How one next-event sample counts at a surface point in the reference tracer.
//
// For illuminance — at sensors, and at a Lambertian surface, whose ρ/π multiplies the sum — a
// sample counts once: weight 1, and continuation rays that reach a light add nothing. At a
// glossy surface (material/metallic_roughness.h) seen from v, a sample of direction l counts
// f(l, v) times its multiple-importance weight against the BRDF sampling that continues the
// path (the power heuristic, β = 2; Veach 1997, "Robust Monte Carlo Methods for Light
// Transport Simulation", §9.2.4):
//     w_light = p_light² / (p_light² + p_brdf²),
// p_light the density (per steradian) with which the light's sampler drew l — infinite for a
// point source, which no BRDF sample can reach (weight 1) — and p_brdf the BRDF sampler's.
// A continuation ray from a glossy surface that reaches the same light adds its radiance with
// w_brdf = 1 − w_light (reference/reference_portals.h escaped_radiance); so either strategy may
// find a direction and no direction is counted twice. Pinned by
// tests/reference/reference_glossy_test.cpp.
#pragma once

#include <limits>

#include "material/metallic_roughness.h"
#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

// a² / (a² + b²), 1 when a is infinite.
inline double power_heuristic(double a, double b) {
  if (a == std::numeric_limits<double>::infinity()) return 1;
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0;
}

inline constexpr double kDeltaPdf = std::numeric_limits<double>::infinity();

struct NextEventWeight {
  const MetallicRoughness* glossy = nullptr;  // null: illuminance (weight 1)
  Vec3 n, v;                                  // with glossy: the surface normal and the viewer
  // False where no BRDF sample continues the path to compete (reference/reference_mirror.h):
  // f alone.
  bool competes = true;

  // The weight of a sample toward l drawn with density light_pdf (kDeltaPdf: a point, or a
  // light that continuation rays never reach).
  Rgb operator()(Vec3 l, double light_pdf) const {
    if (glossy == nullptr) return {1, 1, 1};
    const Rgb f = metallic_roughness_brdf(*glossy, n, l, v);
    if (light_pdf == kDeltaPdf || !competes) return f;
    return f * power_heuristic(light_pdf, metallic_roughness_pdf(*glossy, n, l, v));
  }
};

}  // namespace relight
