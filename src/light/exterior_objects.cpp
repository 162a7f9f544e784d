// Dynamic exterior geometry rendered into a portal's shell by ray casting from the portal
// centre; see light/exterior_objects.h.
#include "light/exterior_objects.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/cubemap.h"

namespace relight {

namespace {

bool finite_non_negative(Rgb c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 &&
         c.b >= 0;
}

Rgb clamp_non_negative(Rgb c) {
  return {std::max(c.r, 0.0), std::max(c.g, 0.0), std::max(c.b, 0.0)};
}

}  // namespace

ExteriorScene build_exterior_scene(std::span<const ExteriorObject> objects) {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> object, ids;
  std::vector<Vec3> normals;
  std::vector<Rgb> albedo;
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const ExteriorObject& obj = objects[o];
    if (!finite_non_negative(obj.albedo))
      throw std::invalid_argument("exterior object albedo must be finite and >= 0");
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (const Vec3& p : obj.positions) {
      if (!is_finite(p)) throw std::invalid_argument("exterior object position is not finite");
      positions.push_back(p);
    }
    for (const Triangle& t : obj.triangles) {
      for (const std::uint32_t v : t)
        if (v >= obj.positions.size())
          throw std::invalid_argument("exterior object triangle index out of range");
      const Vec3 a = obj.positions[t[0]], b = obj.positions[t[1]], c = obj.positions[t[2]];
      const Vec3 n = cross(b - a, c - a);
      const double len = length(n);
      normals.push_back(len > 0 ? n / len : Vec3{});
      ids.push_back(static_cast<std::uint32_t>(triangles.size()));
      triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      object.push_back(static_cast<std::uint32_t>(o));
    }
    albedo.push_back(obj.albedo);
  }
  return {RayTracer(positions, triangles, ids), std::move(object), std::move(normals),
          std::move(albedo)};
}

bool sun_visible(const ExteriorScene& scene, Vec3 centre, Vec3 dir) {
  return !scene.tracer.occluded(Ray{centre, dir});
}

Rgb shade_exterior_hit(const ExteriorScene& scene, const RayHit& hit, Vec3 origin, Vec3 dir,
                       const IrradianceSh& sky_irradiance, const SunDisc* sun) {
  Vec3 n = scene.normal[hit.triangle];
  if (n == Vec3{}) n = -dir;  // degenerate triangle: face the viewer
  if (dot(n, dir) > 0) n = -n;
  const Vec3 p = origin + dir * hit.t;
  Rgb e = clamp_non_negative(sky_irradiance.irradiance(n));
  if (sun) {
    const double cos_sun = dot(n, sun->direction);
    if (cos_sun > 0 && !scene.tracer.occluded(Ray{offset_from_surface(p, n), sun->direction})) {
      const double es = sun->normal_illuminance * cos_sun;
      e += Rgb{es, es, es};
    }
  }
  return scene.albedo[scene.object[hit.triangle]] * e * (1.0 / kPi);
}

std::size_t composite_exterior(const ExteriorScene& scene, Vec3 centre, int face_size,
                               int subrays_per_axis, const IrradianceSh& sky_irradiance,
                               const SunDisc* sun, std::span<Rgb> cubemap) {
  const int n = face_size, k = subrays_per_axis;
  if (n < 1 || k < 1 || cubemap.size() != cubemap_texel_count(n))
    throw std::invalid_argument("composite_exterior: bad face size, sub-ray count or cubemap");
  if (scene.tracer.triangle_count() == 0) return 0;
  std::atomic<std::size_t> hit_texels{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cubemap.size(), 64), [&](const auto& range) {
    std::size_t local_hits = 0;
    for (std::size_t index = range.begin(); index != range.end(); ++index) {
      const CubemapTexel t = cubemap_texel_from_index(n, index);
      Rgb sum;
      int hits = 0;
      for (int b = 0; b < k; ++b)
        for (int a = 0; a < k; ++a) {
          const Vec3 d =
              cubemap_direction({t.face, (t.i + (a + 0.5) / k) / n, (t.j + (b + 0.5) / k) / n});
          const RayHit hit = scene.tracer.intersect(Ray{centre, d});
          if (!hit.hit()) continue;
          ++hits;
          sum += shade_exterior_hit(scene, hit, centre, d, sky_irradiance, sun);
        }
      if (hits == 0) continue;
      ++local_hits;
      const double f = static_cast<double>(hits) / (k * k);
      cubemap[index] = cubemap[index] * (1.0 - f) + sum * (1.0 / (k * k));
    }
    hit_texels += local_hits;
  });
  return hit_texels.load();
}

}  // namespace relight
