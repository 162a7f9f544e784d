#include "reference/reference_portals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "material/lambert.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace relight {

namespace {

// Keeps visibility tests off the sampled portal triangle and its neighbours: a ray from x
// to y stops this short of y, and the continuation from y starts this far beyond it.
constexpr double kPortalMargin = 1e-4;  // m

ReferenceFrost make_frost(double frost_deg);  // below, with the other frost helpers

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

// One area sample of portal p's continuous environment (the estimator in the header).
Rgb environment_sample(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays, const NextEventWeight& weight) {
  const ReferencePortal& portal = view.portals.portals[p];
  const PortalPoint y = sample_portal_point(view.mesh, portal, rng);
  const Vec3 d = y.position - origin;
  const double dist2 = dot(d, d);
  const double dist = std::sqrt(dist2);
  if (dist <= kPortalMargin) return {};
  const Vec3 w = d / dist;
  const double cos_x = dot(n, w), cos_y = std::abs(dot(y.normal, w));
  if (cos_x <= 0 || cos_y <= 0) return {};
  // x sees y, y is the first portal crossing, and the exterior lies beyond y.
  ++rays;
  if (view.traced.opaque.occluded({origin, w, 0, dist})) return {};
  ++rays;
  if (view.traced.portals.occluded({origin, w, 0, dist - kPortalMargin})) return {};
  ++rays;
  if (view.traced.opaque.occluded({y.position, w, kPortalMargin})) return {};
  const Rgb radiance = through_glass(portal, y.position, w, false, rng, rays);
  if (weight.glossy == nullptr) return radiance * (cos_x * cos_y / dist2 * portal.area());
  const double pdf = dist2 / (cos_y * portal.area());  // of w, per steradian
  return radiance * weight(w, pdf) * (cos_x / pdf);
}

// One (antithetic) sun-cone sample of portal p's sun disc, if its environment has one.
Rgb sun_sample(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
               std::uint64_t& rays, const NextEventWeight& weight) {
  const std::optional<SunDisc>& sun = view.portals.portals[p].environment.sun();
  if (!sun || view.portals.portals[p].spreads_sun()) return {};  // in the area samples
  Rgb e;
  for (const Vec3& w : sample_sun_directions(*sun, rng)) {
    const double cos_x = dot(n, w);
    if (cos_x <= 0) continue;
    if (escape_portal(view, {origin, w}, rays) != static_cast<std::int32_t>(p)) continue;
    const ReferencePortal& portal = view.portals.portals[p];
    if (portal.exterior && portal.exterior->tracer.occluded({origin, w})) continue;
    const double l = 0.5 * sun->luminance * sun->solid_angle * cos_x * portal.transmittance(w);
    e += weight(w, 1 / sun->solid_angle) * l;
  }
  return view.portals.portals[p].tint * e;
}

}  // namespace

std::array<Vec3, 2> sample_sun_directions(const SunDisc& sun, Pcg32& rng) {
  const double cos_a = 1 - rng.next_double() * (1 - sun.cos_angular_radius);
  const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
  const double phi = 2 * kPi * rng.next_double();
  const double x = std::cos(phi) * sin_a, y = std::sin(phi) * sin_a;
  const Frame frame = frame_from_normal(sun.direction);
  return {normalize(frame.to_world({x, y, cos_a})), normalize(frame.to_world({-x, -y, cos_a}))};
}

ReferencePortals make_reference_portals(const Scene& scene, const PreparedMesh& mesh,
                                        std::vector<Environment> environments,
                                        const std::vector<std::vector<ExteriorObject>>& exterior) {
  if (environments.size() != scene.portals.size()) {
    throw std::invalid_argument("make_reference_portals: " + std::to_string(environments.size()) +
                                " environments for " + std::to_string(scene.portals.size()) +
                                " portals");
  }
  ReferencePortals out;
  const std::vector<int> material_portal = scene.portal_of_material();  // −1 = kNoPortal
  for (std::size_t p = 0; p < scene.portals.size(); ++p) {
    out.portals.push_back({scene.portals[p].name,
                           std::move(environments[p]),
                           scene.portals[p].tint,
                           {0, 0, 1},
                           {},
                           scene.portals[p].glazing,
                           {},
                           {},
                           {}});
    if (scene.portals[p].frost_deg > 0) {
      out.portals.back().frost =
          std::make_shared<const ReferenceFrost>(make_frost(scene.portals[p].frost_deg));
    }
    if (p >= exterior.size() || exterior[p].empty()) continue;
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
    std::vector<Rgb> albedo;
    for (const ExteriorObject& o : exterior[p]) {
      const auto first = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), o.positions.begin(), o.positions.end());
      for (const Triangle& t : o.triangles) {
        triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
        albedo.push_back(o.albedo);
      }
    }
    RayTracer tracer(positions, triangles, sequential_ids(triangles.size()));
    out.portals.back().exterior = std::make_shared<const ReferenceExterior>(ReferenceExterior{
        std::move(positions), std::move(triangles), std::move(albedo), std::move(tracer)});
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
  // Outward: the portal's mean face normal, turned away from the mesh's centroid (a window or
  // skylight lies on the room's boundary, the room on the centroid's side).
  Vec3 centroid;
  for (const Vec3& v : mesh.positions) centroid += v;
  if (!mesh.positions.empty()) centroid = centroid / static_cast<double>(mesh.positions.size());
  for (ReferencePortal& portal : out.portals) {
    Vec3 normal, centre;
    for (const std::uint32_t t : portal.triangles) {
      const Triangle& tri = mesh.triangles[t];
      const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
      normal += cross(b - a, c - a);  // twice the area, along the face normal
      centre += (a + b + c) * (length(cross(b - a, c - a)) / 6);
    }
    if (portal.area() <= 0) continue;
    centre = centre / portal.area();
    const Vec3 away = centre - centroid;
    if (length(normal) > 0) {
      normal = normalize(normal);
      portal.outward = dot(normal, away) >= 0 ? normal : normal * -1.0;
    } else if (length(away) > 0) {
      portal.outward = normalize(away);
    }
  }
  return out;
}

std::optional<Rgb> exterior_radiance(const ReferencePortal& portal, const Ray& ray, Pcg32& rng,
                                     std::uint64_t& rays) {
  if (!portal.exterior) return std::nullopt;
  const ReferenceExterior& x = *portal.exterior;
  ++rays;
  const RayHit hit = x.tracer.intersect(ray);
  if (!hit.hit()) return std::nullopt;
  const Triangle& t = x.triangles[hit.triangle];
  const Vec3 a = x.positions[t[0]], b = x.positions[t[1]], c = x.positions[t[2]];
  Vec3 n = normalize(cross(b - a, c - a));
  if (dot(n, ray.direction) > 0) n = -n;  // two-sided: the side the ray sees
  const Vec3 h = a * (1 - hit.u - hit.v) + b * hit.u + c * hit.v;
  const Vec3 from = offset_from_surface(h, n);
  Rgb e;
  if (const std::optional<SunDisc>& sun = portal.environment.sun()) {
    const double cos_s = dot(n, sun->direction);
    ++rays;
    if (cos_s > 0 && !x.tracer.occluded({from, sun->direction})) {
      e += Rgb{1, 1, 1} * (sun->normal_illuminance * cos_s);
    }
  }
  // The continuous environment: one cosine-distributed direction, E ≈ π·L.
  const double u1 = rng.next_double(), u2 = rng.next_double();
  const Vec3 w = frame_from_normal(n).to_world(sample_cosine_hemisphere(u1, u2));
  ++rays;
  if (!x.tracer.occluded({from, w})) e += portal.environment.diffuse_radiance(w) * kPi;
  return lambertian_radiance(x.albedo[hit.triangle], e);
}

namespace {

double frost_kernel(double cos_angle, double sigma) {
  return std::exp((cos_angle - 1) / (sigma * sigma));
}

ReferenceFrost make_frost(double frost_deg) {
  ReferenceFrost f;
  f.sigma = radians(frost_deg);
  const double s2 = f.sigma * f.sigma;
  f.normaliser = 2 * kPi * s2 * (1 - std::exp(-2 / s2));
  // Z(c) = ∫_{θ'' < 90°} K(ω, ω'')·cos θ'' dω'' with ω at cos θ = c, by the midpoint rule.
  constexpr int kTheta = 512, kPhi = 256;
  for (int i = 0; i <= 256; ++i) {
    const double c = i / 256.0, s = std::sqrt(std::max(0.0, 1 - c * c));
    double z = 0;
    for (int a = 0; a < kTheta; ++a) {
      const double theta = (a + 0.5) * (kPi / 2) / kTheta;
      const double ct = std::cos(theta), st = std::sin(theta);
      double ring = 0;
      for (int b = 0; b < kPhi; ++b) {
        const double phi = (b + 0.5) * 2 * kPi / kPhi;
        ring += frost_kernel(s * st * std::cos(phi) + c * ct, f.sigma);
      }
      z += ring * ct * st * (kPi / 2 / kTheta) * (2 * kPi / kPhi);
    }
    f.z_of_cos.push_back(z);
  }
  return f;
}

double frost_z(const ReferenceFrost& f, double c) {
  const double x = std::clamp(c, 0.0, 1.0) * 256;
  const auto i = std::min(static_cast<std::size_t>(x), std::size_t{255});
  const double t = x - static_cast<double>(i);
  return f.z_of_cos[i] * (1 - t) + f.z_of_cos[i + 1] * t;
}

// A direction drawn from K(·, axis): the von Mises–Fisher distribution of κ = 1/σ².
Vec3 sample_frost_direction(Vec3 axis, double sigma, Pcg32& rng) {
  const double kappa = 1 / (sigma * sigma);
  const double u = rng.next_double();
  const double c = std::clamp(1 + std::log(u + (1 - u) * std::exp(-2 * kappa)) / kappa, -1.0, 1.0);
  const double s = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * kPi * rng.next_double();
  return normalize(frame_from_normal(axis).to_world({s * std::cos(phi), s * std::sin(phi), c}));
}

// What lies outside along `dir`: the first exterior object, else the environment.
Rgb seen_outside(const ReferencePortal& portal, Vec3 from, Vec3 dir, bool with_sun, Pcg32& rng,
                 std::uint64_t& rays) {
  if (const std::optional<Rgb> object = exterior_radiance(portal, {from, dir, 1e-4}, rng, rays)) {
    return *object;
  }
  return with_sun ? portal.environment.radiance(dir) : portal.environment.diffuse_radiance(dir);
}

}  // namespace

Rgb through_glass(const ReferencePortal& portal, Vec3 from, Vec3 dir, bool with_sun, Pcg32& rng,
                  std::uint64_t& rays) {
  const bool diffusing = portal.glazing && portal.glazing->diffusing;
  if (!portal.frost && !diffusing) {
    return portal.tint * seen_outside(portal, from, dir, with_sun, rng, rays) *
           portal.transmittance(dir);
  }
  Rgb l;
  const std::optional<SunDisc>& sun = portal.environment.sun();
  const double cs = sun ? dot(sun->direction, portal.outward) : 0.0;
  const auto sun_seen = [&] {
    ++rays;
    return cs > 0 && !(portal.exterior && portal.exterior->tracer.occluded({from, sun->direction}));
  };
  if (diffusing) {
    const Vec3 w = frame_from_normal(portal.outward)
                       .to_world(sample_cosine_hemisphere(rng.next_double(), rng.next_double()));
    l += seen_outside(portal, from, w, false, rng, rays) * portal.transmittance(w);
    if (sun && sun_seen()) {
      const double e =
          sun->integrated_luminance() * cs * portal.transmittance(sun->direction) / kPi;
      l += Rgb{e, e, e};
    }
    return portal.tint * l;
  }
  const ReferenceFrost& f = *portal.frost;
  const Vec3 w = sample_frost_direction(dir, f.sigma, rng);
  const double c = dot(w, portal.outward);
  if (c > 0) {
    l += seen_outside(portal, from, w, false, rng, rays) *
         (c * f.normaliser / frost_z(f, c) * portal.transmittance(w));
  }
  if (sun && sun_seen()) {
    const double e = sun->integrated_luminance() * cs * portal.transmittance(sun->direction) *
                     frost_kernel(dot(sun->direction, dir), f.sigma) / frost_z(f, cs);
    l += Rgb{e, e, e};
  }
  return portal.tint * l;
}

std::int32_t escape_portal(const ExteriorView& view, const Ray& ray, std::uint64_t& rays) {
  ++rays;
  if (view.traced.opaque.occluded(ray)) return kNoPortal;
  ++rays;
  const RayHit hit = view.traced.portals.intersect(ray);
  return hit.hit() ? view.portals.triangle_portal[hit.triangle] : kNoPortal;
}

Rgb portal_illuminance(const ExteriorView& view, Vec3 origin, Vec3 n, Pcg32& rng,
                       std::uint64_t& rays, const NextEventWeight& weight,
                       const std::function<double(std::size_t)>& sun_weight) {
  Rgb e;
  for (std::size_t p = 0; p < view.portals.portals.size(); ++p) {
    if (view.portals.portals[p].area() <= 0) continue;
    e += environment_sample(view, p, origin, n, rng, rays, weight);
    const Rgb sun = sun_sample(view, p, origin, n, rng, rays, weight);
    e += sun_weight ? sun * sun_weight(p) : sun;
  }
  return e;
}

Rgb portal_sun_illuminance(const ExteriorView& view, std::size_t p, Vec3 origin, Vec3 n, Pcg32& rng,
                           std::uint64_t& rays, const NextEventWeight& weight) {
  if (view.portals.portals[p].area() <= 0) return {};
  return sun_sample(view, p, origin, n, rng, rays, weight);
}

Rgb escaped_radiance(const ExteriorView& view, const Ray& ray, double brdf_pdf, Pcg32& rng,
                     std::uint64_t& rays, const std::function<double(std::size_t)>& sun_weight) {
  ++rays;
  if (view.traced.opaque.occluded(ray)) return {};
  ++rays;
  const RayHit hit = view.traced.portals.intersect(ray);
  if (!hit.hit()) return {};
  const std::int32_t index = view.portals.triangle_portal[hit.triangle];
  if (index == kNoPortal) return {};
  const ReferencePortal& portal = view.portals.portals[static_cast<std::size_t>(index)];
  if (portal.area() <= 0) return {};
  const Vec3 w = ray.direction;
  const double cos_y = std::abs(dot(geometric_normal(view.mesh, hit.triangle), w));
  if (cos_y <= 0) return {};
  // The area strategy's density of w (environment_sample), against the BRDF's.
  const double area_pdf = hit.t * hit.t / (cos_y * portal.area());
  const Vec3 y = ray.origin + w * hit.t;
  Rgb l = through_glass(portal, y, w, false, rng, rays) * power_heuristic(brdf_pdf, area_pdf);
  const std::optional<SunDisc>& sun = portal.environment.sun();
  if (sun && !portal.spreads_sun() && dot(w, sun->direction) >= sun->cos_angular_radius) {
    ++rays;
    if (!(portal.exterior && portal.exterior->tracer.occluded({ray.origin, w}))) {
      const double disc = sun->luminance * power_heuristic(brdf_pdf, 1 / sun->solid_angle) *
                          (sun_weight ? sun_weight(static_cast<std::size_t>(index)) : 1.0);
      l += portal.tint * Rgb{disc, disc, disc} * portal.transmittance(w);
    }
  }
  return l;
}

}  // namespace relight
