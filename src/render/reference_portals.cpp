#include "render/reference_portals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "math/frame.h"

namespace relight {

namespace {

// Keeps visibility tests off the sampled portal triangle and its neighbours: a ray from x
// to y stops this short of y, and the continuation from y starts this far beyond it.
constexpr double kPortalMargin = 1e-4;  // m

double triangle_area(const PreparedMesh& mesh, std::uint32_t triangle) {
  const Triangle& t = mesh.triangles[triangle];
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  return 0.5 * length(cross(b - a, c - a));
}

struct PortalPoint {
  Vec3 position, normal;
};

// A point uniform over the portal's area (pdf 1 / area): a triangle in proportion to its
// area, then uniform in it (the square-root warp of the barycentrics).
PortalPoint sample_portal_point(const PreparedMesh& mesh, const ReferencePortal& portal,
                                Pcg32& rng) {
  const double pick = rng.next_double() * portal.area();
  const auto it =
      std::upper_bound(portal.cumulative_area.begin(), portal.cumulative_area.end(), pick);
  const std::size_t k = std::min(static_cast<std::size_t>(it - portal.cumulative_area.begin()),
                                 portal.triangles.size() - 1);
  const std::uint32_t triangle = portal.triangles[k];
  const double r = std::sqrt(rng.next_double()), s = rng.next_double();
  return {point_on_triangle(mesh, triangle, r * (1 - s), r * s), geometric_normal(mesh, triangle)};
}

// Two directions in the cone of the sun disc, each uniform in it (pdf 1 / solid_angle)
// and mirror images of each other about its axis (antithetic: their cosines to any normal
// sum to 2·cos α·cos θ_s, so the pair's estimate hardly varies where both are unoccluded).
std::array<Vec3, 2> sample_sun_directions(const SunDisc& sun, Pcg32& rng) {
  const double cos_a = 1 - rng.next_double() * (1 - sun.cos_angular_radius);
  const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
  const double phi = 2 * kPi * rng.next_double();
  const double x = std::cos(phi) * sin_a, y = std::sin(phi) * sin_a;
  const Frame frame = frame_from_normal(sun.direction);
  return {normalize(frame.to_world({x, y, cos_a})), normalize(frame.to_world({-x, -y, cos_a}))};
}

// One area sample of portal p's continuous environment (the estimator in the header).
Rgb environment_sample(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays) {
  const ReferencePortal& portal = view.portals.portals[p];
  const PortalPoint y = sample_portal_point(view.mesh, portal, rng);
  const Vec3 d = y.position - origin;
  const double dist2 = dot(d, d);
  const double dist = std::sqrt(dist2);
  if (dist <= kPortalMargin) return {};
  const Vec3 w = d / dist;
  const double cos_x = dot(n, w), cos_y = std::abs(dot(y.normal, w));
  if (cos_x <= 0 || cos_y <= 0) return {};
  const Rgb radiance = portal.tint * portal.environment.diffuse_radiance(w);
  if (max_component(radiance) <= 0) return {};
  // x sees y, y is the first portal crossing, and the exterior lies beyond y.
  ++rays;
  if (view.traced.opaque.occluded({origin, w, 0, dist})) return {};
  ++rays;
  if (view.traced.portals.occluded({origin, w, 0, dist - kPortalMargin})) return {};
  ++rays;
  if (view.traced.opaque.occluded({y.position, w, kPortalMargin})) return {};
  return radiance * (cos_x * cos_y / dist2 * portal.area());
}

// One (antithetic) sun-cone sample of portal p's sun disc, if its environment has one.
Rgb sun_sample(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
               std::uint64_t& rays) {
  const std::optional<SunDisc>& sun = view.portals.portals[p].environment.sun();
  if (!sun) return {};
  double e = 0;
  for (const Vec3& w : sample_sun_directions(*sun, rng)) {
    const double cos_x = dot(n, w);
    if (cos_x <= 0) continue;
    if (escape_portal(view, {origin, w}, rays) != static_cast<std::int32_t>(p)) continue;
    e += 0.5 * sun->luminance * sun->solid_angle * cos_x;
  }
  return view.portals.portals[p].tint * Rgb{e, e, e};
}

}  // namespace

ReferencePortals make_reference_portals(const Scene& scene, const PreparedMesh& mesh,
                                        std::vector<Environment> environments) {
  if (environments.size() != scene.portals.size()) {
    throw std::invalid_argument("make_reference_portals: " + std::to_string(environments.size()) +
                                " environments for " + std::to_string(scene.portals.size()) +
                                " portals");
  }
  ReferencePortals out;
  const std::vector<int> material_portal = scene.portal_of_material();  // −1 = kNoPortal
  for (std::size_t p = 0; p < scene.portals.size(); ++p) {
    out.portals.push_back(
        {scene.portals[p].name, std::move(environments[p]), scene.portals[p].tint, {}, {}});
  }
  out.triangle_portal.reserve(mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto p = static_cast<std::int32_t>(material_portal.at(mesh.triangle_material[t]));
    out.triangle_portal.push_back(p);
    if (p == kNoPortal) continue;
    const double area = triangle_area(mesh, t);
    if (area <= 0) continue;
    ReferencePortal& portal = out.portals[static_cast<std::size_t>(p)];
    portal.triangles.push_back(t);
    portal.cumulative_area.push_back(portal.area() + area);
  }
  return out;
}

std::int32_t escape_portal(const ExteriorView& view, const Ray& ray, std::uint64_t& rays) {
  ++rays;
  if (view.traced.opaque.occluded(ray)) return kNoPortal;
  ++rays;
  const RayHit hit = view.traced.portals.intersect(ray);
  return hit.hit() ? view.portals.triangle_portal[hit.triangle] : kNoPortal;
}

Rgb portal_illuminance(const ExteriorView& view, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays) {
  Rgb e;
  for (std::size_t p = 0; p < view.portals.portals.size(); ++p) {
    if (view.portals.portals[p].area() <= 0) continue;
    e += environment_sample(view, p, origin, n, rng, rays);
    e += sun_sample(view, p, origin, n, rng, rays);
  }
  return e;
}

}  // namespace relight
