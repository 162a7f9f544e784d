#include "sources/emitters/emitter_direct.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace relight {

namespace {

// The polygon (at most 4 corners, relative to p) of the triangle on the side n·q ≥ 0.
struct Polygon {
  std::array<Vec3, 4> corners;
  int count = 0;
};

Polygon clip_to_upper_side(const std::array<Vec3, 3>& q, Vec3 n) {
  Polygon out;
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = q[static_cast<std::size_t>(i)], b = q[static_cast<std::size_t>((i + 1) % 3)];
    const double da = dot(n, a), db = dot(n, b);
    if (da >= 0) out.corners[static_cast<std::size_t>(out.count++)] = a;
    if ((da >= 0) != (db >= 0)) {
      out.corners[static_cast<std::size_t>(out.count++)] = a + (b - a) * (da / (da - db));
    }
  }
  return out;
}

}  // namespace

double triangle_irradiance_factor(Vec3 p, Vec3 n, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 face = cross(b - a, c - a);
  if (dot(face, p - a) <= 0) return 0;  // behind the emitting side (or in its plane)
  const Polygon poly = clip_to_upper_side({a - p, b - p, c - p}, n);
  if (poly.count < 3) return 0;
  double sum = 0;
  for (int i = 0; i < poly.count; ++i) {
    const Vec3 u = poly.corners[static_cast<std::size_t>(i)];
    const Vec3 v = poly.corners[static_cast<std::size_t>((i + 1) % poly.count)];
    const double lu = length(u), lv = length(v);
    if (lu <= 0 || lv <= 0) continue;
    const Vec3 g = cross(u, v);
    const double lg = length(g);
    if (lg <= 0) continue;
    const double theta = std::atan2(lg, dot(u, v));
    sum += theta * dot(n, g) / lg;
  }
  return 0.5 * std::abs(sum);
}

namespace {

// The solid angle of the triangle (a, b, c), corners relative to the eye (Van Oosterom and
// Strackee 1983: tan(Ω/2) = |a·(b×c)| / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|)).
double triangle_solid_angle(Vec3 a, Vec3 b, Vec3 c) {
  const double la = length(a), lb = length(b), lc = length(c);
  const double num = std::abs(dot(a, cross(b, c)));
  const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * std::atan2(num, den);
}

// Emitter triangle t at p (unit normal n, shadow rays from `origin`): its unoccluded factor
// (triangle_irradiance_factor) and the visible fraction of it, from m × m stratified points on
// the triangle (the square-root warp of a grid of cell centres), each weighted by its
// unoccluded contribution.
struct TriangleSeen {
  double factor = 0;
  double visible = 1;
};

TriangleSeen triangle_seen(const PlacedEmitters& emitters, std::size_t t,
                           const Occluders* occluders, Vec3 p, Vec3 n, Vec3 origin, int m) {
  TriangleSeen out;
  const Triangle& tri = emitters.triangles[t];
  const Vec3 a = emitters.positions[tri[0]], b = emitters.positions[tri[1]],
             c = emitters.positions[tri[2]];
  out.factor = triangle_irradiance_factor(p, n, a, b, c);
  if (out.factor <= 0 || occluders == nullptr || occluders->triangle_count() == 0) return out;
  const Vec3 normal = emitters.normals[t];
  double total = 0, seen = 0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const double su = std::sqrt((i + 0.5) / m), v = (j + 0.5) / m;
      const Vec3 y = a * (1 - su) + b * (su * (1 - v)) + c * (su * v);
      const Vec3 d = y - p;
      const double dist2 = dot(d, d);
      if (dist2 <= 0) continue;
      const Vec3 w = d / std::sqrt(dist2);
      const double weight = std::max(0.0, dot(n, w)) * std::max(0.0, -dot(normal, w)) / dist2;
      if (weight <= 0) continue;
      total += weight;
      if (!occluders->occluded({origin, y - origin, 0, 1 - 1e-4})) seen += weight;
    }
  }
  out.visible = total > 0 ? seen / total : 1;
  return out;
}

int samples_per_side(int visibility_samples) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(visibility_samples))));
}

}  // namespace

Rgb emitter_direct_irradiance(const PlacedEmitters& emitters, const Occluders* occluders, Vec3 p,
                              Vec3 n, int visibility_samples) {
  const int m = samples_per_side(visibility_samples);
  const Vec3 origin = offset_from_surface(p, n);
  Rgb e;
  for (std::size_t t = 0; t < emitters.triangles.size(); ++t) {
    const Rgb& radiance = emitters.triangle_radiance[t];
    if (max_component(radiance) <= 0) continue;
    const TriangleSeen seen = triangle_seen(emitters, t, occluders, p, n, origin, m);
    if (seen.factor > 0) e += radiance * (seen.factor * seen.visible);
  }
  return e;
}

SeenLight emitter_seen_from(const PlacedEmitters& emitters, std::size_t k,
                            const Occluders* occluders, Vec3 p, Vec3 n, bool with_luminance,
                            int visibility_samples) {
  const int m = samples_per_side(visibility_samples);
  const Vec3 origin = offset_from_surface(p, n);
  SeenLight out;
  out.area = true;
  Vec3 toward;
  for (std::size_t t = 0; t < emitters.triangles.size(); ++t) {
    if (emitters.emitter_of_triangle[t] != k) continue;
    const Rgb& radiance = emitters.triangle_radiance[t];
    if (max_component(radiance) <= 0) continue;
    const TriangleSeen seen = triangle_seen(emitters, t, occluders, p, n, origin, m);
    if (!(seen.factor > 0) || !(seen.visible > 0)) continue;
    out.irradiance += radiance * (seen.factor * seen.visible);
    out.in_view = true;
    if (!with_luminance) continue;
    const Triangle& tri = emitters.triangles[t];
    const Vec3 a = emitters.positions[tri[0]] - p, b = emitters.positions[tri[1]] - p,
               c = emitters.positions[tri[2]] - p;
    // The whole triangle's solid angle times its visible fraction: the part behind n's plane
    // is left out of the irradiance, not of what an eye sees of an emitter it looks at.
    const double omega = triangle_solid_angle(a, b, c) * seen.visible;
    out.solid_angle += omega;
    toward += normalize(a + b + c) * omega;
  }
  if (out.in_view && with_luminance) {
    out.direction = length(toward) > 0 ? normalize(toward) : Vec3{};
    out.luminance = luminance(emitters.radiance.at(k));
  }
  return out;
}

}  // namespace relight
