#include "reference/reference_emitters.h"

#include <algorithm>
#include <cmath>

namespace relight {

ReferenceEmitters make_reference_emitters(PlacedEmitters placed) {
  ReferenceEmitters out;
  double sum = 0;
  for (std::size_t t = 0; t < placed.triangles.size(); ++t) {
    const Triangle& tri = placed.triangles[t];
    const Vec3 a = placed.positions[tri[0]];
    const double area =
        0.5 * length(cross(placed.positions[tri[1]] - a, placed.positions[tri[2]] - a));
    const double weight = area * luminance(placed.triangle_radiance[t]);
    if (!(weight > 0)) continue;
    sum += weight;
    out.triangles.push_back(static_cast<std::uint32_t>(t));
    out.cumulative.push_back(sum);
  }
  out.placed = std::move(placed);
  return out;
}

Rgb emitter_illuminance(const ReferenceEmitters& emitters, const RayTracer& occluders, Vec3 origin,
                        Vec3 n, Pcg32& rng, std::uint64_t& rays, const NextEventWeight& weight) {
  if (emitters.empty()) return {};
  const double total = emitters.cumulative.back();
  const double pick = rng.next_double() * total;
  const std::size_t i = static_cast<std::size_t>(
      std::upper_bound(emitters.cumulative.begin(), emitters.cumulative.end(), pick) -
      emitters.cumulative.begin());
  const std::size_t k = std::min(i, emitters.triangles.size() - 1);
  const std::uint32_t t = emitters.triangles[k];
  const PlacedEmitters& e = emitters.placed;
  const Triangle& tri = e.triangles[t];
  const Vec3 a = e.positions[tri[0]], b = e.positions[tri[1]], c = e.positions[tri[2]];
  const double area = 0.5 * length(cross(b - a, c - a));
  const double probability =
      (emitters.cumulative[k] - (k > 0 ? emitters.cumulative[k - 1] : 0.0)) / total;
  // A uniform point on the triangle (the square-root warp).
  const double su = std::sqrt(rng.next_double()), v = rng.next_double();
  const Vec3 y = a * (1 - su) + b * (su * (1 - v)) + c * (su * v);
  const Vec3 d = y - origin;
  const double dist2 = dot(d, d);
  if (dist2 <= 0) return {};
  const double dist = std::sqrt(dist2);
  const Vec3 w = d / dist;
  const double cos_x = dot(n, w), cos_y = -dot(e.normals[t], w);
  if (cos_x <= 0 || cos_y <= 0) return {};
  ++rays;
  if (occluders.occluded({origin, w, 0, dist * (1 - 1e-6)})) return {};
  const Rgb e_sample = e.triangle_radiance[t] * (cos_x * cos_y / dist2 * area / probability);
  // Continuation rays pass through emitters: this is the only strategy that finds them.
  return weight.glossy == nullptr ? e_sample : e_sample * weight(w, kDeltaPdf);
}

}  // namespace relight
