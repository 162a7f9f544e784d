#include "render/glossy_pixels.h"

#include "math/sampling.h"
#include "trace/traced_scene.h"

namespace relight {

Rgb glossy_pixel_radiance(const GlossyPixelScene& scene, const MetallicRoughness& m, Vec3 p, Vec3 n,
                          Vec3 v, int samples, std::uint64_t seed) {
  Rgb l = scene.direct(m, p, n, v);
  Pcg32 rng(seed, 0x9e3779b97f4a7c15ull);
  const Vec3 origin = offset_from_surface(p, n);
  Rgb gathered;
  const MetallicRoughnessToward toward(m, n, v);
  for (int i = 0; i < samples; ++i) {
    const double u0 = rng.next_double(), u1 = rng.next_double(), u2 = rng.next_double();
    const BrdfSample s = sample_metallic_roughness(m, n, v, u0, u1, u2);
    const double cos_l = dot(s.l, n);
    if (s.pdf <= 0 || cos_l <= 0) continue;
    const Rgb weight = toward(s.l) * (cos_l / s.pdf);
    const RayHit hit = scene.visible.intersect({origin, s.l});
    if (!hit.hit()) {
      gathered += weight * scene.outside(origin, s.l);
      continue;
    }
    const Triangle& t = scene.triangles[hit.triangle];
    const Vec3 a = scene.positions[t[0]], b = scene.positions[t[1]], c = scene.positions[t[2]];
    if (dot(cross(b - a, c - a), s.l) >= 0) continue;  // a back face: black
    const double bary[3] = {1 - hit.u - hit.v, hit.u, hit.v};
    Rgb seen;
    for (int k = 0; k < 3; ++k) {
      const std::size_t at = 3 * std::size_t{t[k]};
      seen += Rgb{scene.vertex_radiance[at], scene.vertex_radiance[at + 1],
                  scene.vertex_radiance[at + 2]} *
              bary[k];
    }
    gathered += weight * seen;
  }
  if (samples > 0) l += gathered / samples;
  return l;
}

}  // namespace relight
