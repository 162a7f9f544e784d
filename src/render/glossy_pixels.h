// Glossy surfaces in `relight render --direct pixel`: the luminance a glossy surface sends toward
// the eye, per pixel,
//   L(v) = Σ_lights f(l, v) E_l  +  (1/N) Σ_i f(l_i, v) cos θ_i / p(l_i) · L_room(l_i),
// the luminaires' and suns' direct light exact at the hit (their highlights), and the room's
// reflection gathered by N BRDF samples (sample_metallic_roughness) that find either a surface —
// its luminance interpolated from the relit vertices (ρ/π E, the transfer's own light) — or a
// window's exterior (the shell, the sun disc left to the exact term). Emitters light it as the
// diffuse surface of the same hemispherical albedo (an area light's highlight would need its
// own sampling). Pinned by tests/cli/glossy_probe_test.cpp (image blocks against the
// reference).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "material/metallic_roughness.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle_soup.h"
#include "trace/ray_tracer.h"

namespace relight {

struct GlossyPixelScene {
  const RayTracer& visible;  // ids index `triangles`
  const std::vector<Vec3>& positions;
  const std::vector<Triangle>& triangles;
  std::span<const float> vertex_radiance;  // 3 per vertex, cd/m²
  // Luminance arriving along a ray that met no surface (through a window; 0 elsewhere).
  std::function<Rgb(Vec3 origin, Vec3 dir)> outside;
  // Direct light at p (normal n) reflected toward v by the BRDF m: luminaires, suns, emitters.
  std::function<Rgb(const MetallicRoughness& m, Vec3 p, Vec3 n, Vec3 v)> direct;
};

// L(v) at p with unit normal n, with `samples` BRDF samples from a stream seeded by `seed`.
Rgb glossy_pixel_radiance(const GlossyPixelScene& scene, const MetallicRoughness& m, Vec3 p, Vec3 n,
                          Vec3 v, int samples, std::uint64_t seed);

}  // namespace relight
