#include "reference/reference_tracer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "material/lambert.h"
#include "material/material_reflectance.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "reference/reference_mirror.h"

namespace relight {

namespace {

// Per-sample state: the random stream and a count of rays cast (for Mrays/s).
struct PathContext {
  const ReferenceScene& ref;
  Pcg32 rng;
  int max_depth;
  // Surfaces a path from a sensor or a seen point may still reflect at (max_bounces − 1).
  int hits = std::numeric_limits<int>::max();
  std::uint64_t rays = 0;
};

PathContext path_context(const ReferenceScene& ref, const ReferenceSettings& settings,
                         std::uint64_t stream) {
  PathContext ctx{ref, Pcg32(settings.seed, stream), settings.max_depth};
  if (settings.max_bounces > 0) ctx.hits = settings.max_bounces - 1;
  return ctx;
}

// Which luminaires a direct estimate covers: sensors evaluate point sources once and
// average the ones with openings over their samples.
enum class Sources { kAll, kPoints, kOpenings };

// A uniformly random point of the luminous opening, relative to the photometric centre.
Vec3 opening_point(const ReferenceOpening& o, const PlacedLuminaire& l, Pcg32& rng) {
  double s = 0, t = 0;
  do {
    s = rng.next_double() - 0.5;
    t = rng.next_double() - 0.5;
  } while (o.round && 4 * (s * s + t * t) > 1);
  const double h = rng.next_double() - 0.5;
  const PhotometricFrame& f = l.frame;
  return f.c0 * (s * o.length) + f.c90 * (t * o.width) - f.aim * (h * o.height);
}

// Luminaire j's light at a surface point (`origin` pushed off it, unit normal n): I(−w) cos θ
// / d² when the luminaire is seen (through a random point of its opening), w toward it.
Rgb luminaire_light(PathContext& ctx, std::size_t j, Vec3 origin, Vec3 n, Vec3& w) {
  const PlacedLuminaire& l = ctx.ref.luminaires[j];
  const ReferenceOpening& opening = ctx.ref.openings[j];
  const Vec3 d = l.position - origin;
  const double dist2 = dot(d, d);
  const double dist = std::sqrt(dist2);
  if (dist <= kLightMargin) return {};
  w = d / dist;
  const double cos_theta = dot(n, w);
  if (cos_theta <= 0) return {};
  const Rgb intensity = l.intensity_toward(-w);
  if (max_component(intensity) <= 0) return {};
  ++ctx.rays;
  Vec3 to_light = d;
  if (!opening.is_point()) to_light += opening_point(opening, l, ctx.rng);
  const double span = length(to_light);
  if (span > kLightMargin &&
      ctx.ref.traced.opaque.occluded({origin, to_light / span, 0, span - kLightMargin})) {
    return {};
  }
  return intensity * (cos_theta / dist2);
}

// How a path reached a glossy point of a near-mirror plane: by cosine sampling at a Lambertian
// point (`from`, the ray's origin), whose density `pdf` competes with the mirror lobe about
// each luminaire's image there (reference/reference_mirror.h). Without a plane: no competition.
struct MirrorArrival {
  const MirrorPlane* plane = nullptr;
  double alpha = 0;
  Vec3 from, direction;
  double pdf = 0;

  // The cosine strategy's power-heuristic weight for the light at `light`.
  double weight(Vec3 light) const {
    if (plane == nullptr) return 1;
    return weight(mirror_lobe(*plane, alpha, from, light));
  }
  // ... and for a sun.
  double sun_weight(const SunDisc& sun) const {
    if (plane == nullptr) return 1;
    return weight(mirror_sun_lobe(*plane, alpha, from, sun.direction, sun.angular_radius));
  }
  double weight(const std::optional<MirrorLobe>& lobe) const {
    return lobe ? power_heuristic(pdf, mirror_lobe_pdf(*lobe, direction)) : 1;
  }
};

Rgb direct_illuminance(PathContext& ctx, Vec3 p, Vec3 n, Sources sources = Sources::kAll,
                       const NextEventWeight& weight = {}, const MirrorArrival& arrival = {}) {
  const ReferenceScene& ref = ctx.ref;
  Rgb e;
  const Vec3 origin = offset_from_surface(p, n);
  for (std::size_t j = 0; j < ref.luminaires.size(); ++j) {
    const ReferenceOpening& opening = ref.openings[j];
    if ((sources == Sources::kPoints && !opening.is_point()) ||
        (sources == Sources::kOpenings && opening.is_point())) {
      continue;
    }
    Vec3 w;
    const Rgb light = luminaire_light(ctx, j, origin, n, w);
    if (max_component(light) <= 0) continue;
    e += light * weight(w, kDeltaPdf) * arrival.weight(ref.luminaires[j].position);
  }
  return e;
}

struct SurfaceHit {
  Vec3 position;
  Vec3 normal;
  Rgb albedo;
  std::optional<MetallicRoughness> glossy;  // none: Lambertian
  std::int32_t mirror = -1;                 // its near-mirror plane, or −1
};

// The first front-facing opaque surface along the ray; false for misses and back faces (with
// `back_side`, set when the ray met the back of a surface).
bool trace_surface(PathContext& ctx, const Ray& ray, SurfaceHit& out, bool* back_side = nullptr) {
  const ReferenceScene& ref = ctx.ref;
  ++ctx.rays;
  const RayHit hit = ref.traced.opaque.intersect(ray);
  if (back_side != nullptr) *back_side = false;
  if (!hit.hit()) return false;
  const Vec3 n = geometric_normal(ref.mesh, hit.triangle);
  if (dot(n, ray.direction) >= 0) {  // back sides absorb
    if (back_side != nullptr) *back_side = true;
    return false;
  }
  const std::int32_t glossy =
      hit.triangle < ref.triangle_glossy.size() ? ref.triangle_glossy[hit.triangle] : -1;
  // The base colour times the texture at the point, at full resolution (scene/surface_texture.h).
  const Rgb texture = texture_at(ref.mesh.triangle_textures, hit.triangle, hit.u, hit.v);
  out = {point_on_triangle(ref.mesh, hit.triangle, hit.u, hit.v), n,
         ref.triangle_albedo[hit.triangle] * texture, std::nullopt};
  if (glossy >= 0) {
    out.glossy = ref.glossy[static_cast<std::size_t>(glossy)];
    out.glossy->albedo = out.glossy->albedo * texture;
  }
  if (hit.triangle < ref.triangle_mirror.size()) out.mirror = ref.triangle_mirror[hit.triangle];
  return true;
}

// Daylight through the portals at a surface point (reference/reference_portals.h).
// Per portal, the cosine strategy's weight for its sun at a glossy point reached as `arrival`
// says; none without a mirror plane.
std::function<double(std::size_t)> sun_weights(const ReferencePortals& portals,
                                               const MirrorArrival& arrival) {
  if (arrival.plane == nullptr) return {};
  return [&portals, arrival](std::size_t q) {
    const std::optional<SunDisc>& sun = portals.portals[q].environment.sun();
    return sun ? arrival.sun_weight(*sun) : 1.0;
  };
}

Rgb daylight_illuminance(PathContext& ctx, Vec3 p, Vec3 n, const NextEventWeight& weight = {},
                         const MirrorArrival& arrival = {}) {
  if (ctx.ref.portals.portals.empty()) return {};
  const ExteriorView view{ctx.ref.mesh, ctx.ref.traced, ctx.ref.portals};
  return portal_illuminance(view, offset_from_surface(p, n), n, ctx.rng, ctx.rays, weight,
                            sun_weights(ctx.ref.portals, arrival));
}

// Near-field emitters at a surface point (reference/reference_emitters.h).
Rgb emitters_illuminance(PathContext& ctx, Vec3 p, Vec3 n, const NextEventWeight& weight = {}) {
  if (ctx.ref.emitters.empty()) return {};
  return emitter_illuminance(ctx.ref.emitters, ctx.ref.traced.opaque, offset_from_surface(p, n), n,
                             ctx.rng, ctx.rays, weight);
}

// Whether a ray from `origin` along w leaves the scene: no surface, no portal glass.
bool leaves_scene(PathContext& ctx, const Ray& ray) {
  ctx.rays += 2;
  return !ctx.ref.traced.opaque.occluded(ray) && !ctx.ref.traced.portals.occluded(ray);
}

// The weight of a next-event sample toward w of density light_pdf at a point of normal n
// against the continuation from it: the BRDF's at a glossy point (f times the weight, as
// `weight` gives it), the cosine density's at a Lambertian one.
Rgb open_weight(const NextEventWeight& weight, Vec3 n, Vec3 w, double light_pdf) {
  if (weight.glossy != nullptr) return weight(w, light_pdf);
  const double h = power_heuristic(light_pdf, std::max(0.0, dot(n, w)) / kPi);
  return {h, h, h};
}

// The top-level environment at a surface point by next-event estimation (see the header).
Rgb open_illuminance(PathContext& ctx, Vec3 p, Vec3 n, const NextEventWeight& weight = {}) {
  const ReferenceScene& ref = ctx.ref;
  if (!ref.open_environment) return {};
  const Vec3 origin = offset_from_surface(p, n);
  Rgb e;
  const EnvironmentSampler::Sample s =
      ref.open_sampler->sample(ctx.rng.next_double(), ctx.rng.next_double());
  if (const double c = dot(n, s.direction);
      s.pdf > 0 && c > 0 && leaves_scene(ctx, {origin, s.direction})) {
    e += ref.open_environment->diffuse_radiance(s.direction) *
         open_weight(weight, n, s.direction, s.pdf) * (c / s.pdf);
  }
  if (const std::optional<SunDisc>& sun = ref.open_environment->sun()) {
    // The antithetic pair of the portals' sun samples, half each.
    for (const Vec3& w : sample_sun_directions(*sun, ctx.rng)) {
      if (const double c = dot(n, w); c > 0 && leaves_scene(ctx, {origin, w})) {
        e += open_weight(weight, n, w, 1 / sun->solid_angle) *
             (0.5 * sun->luminance * sun->solid_angle * c);
      }
    }
  }
  return e;
}

// What a continuation ray drawn with density `pdf` that met no surface finds of the top-level
// environment, weighted against its next-event estimate.
Rgb open_escape(PathContext& ctx, const Ray& ray, double pdf) {
  const ReferenceScene& ref = ctx.ref;
  if (!ref.open_environment || pdf <= 0 || !leaves_scene(ctx, ray)) return {};
  const Vec3 w = normalize(ray.direction);
  Rgb l =
      ref.open_environment->diffuse_radiance(w) * power_heuristic(pdf, ref.open_sampler->pdf(w));
  if (const std::optional<SunDisc>& sun = ref.open_environment->sun();
      sun && dot(w, sun->direction) >= sun->cos_angular_radius) {
    l += Rgb{1, 1, 1} * (sun->luminance * power_heuristic(pdf, 1 / sun->solid_angle));
  }
  return l;
}

// What a glossy surface reflects toward v from every light by next-event estimation, each
// sample weighted against the BRDF sample that continues the path (reference/reference_weight.h).
Rgb glossy_next_events(PathContext& ctx, const SurfaceHit& s, Vec3 v,
                       const MirrorArrival& arrival = {}) {
  const NextEventWeight weight{s.glossy ? &*s.glossy : nullptr, s.normal, v};
  return direct_illuminance(ctx, s.position, s.normal, Sources::kAll, weight, arrival) +
         daylight_illuminance(ctx, s.position, s.normal, weight, arrival) +
         emitters_illuminance(ctx, s.position, s.normal, weight) +
         open_illuminance(ctx, s.position, s.normal, weight);
}

// A continuation of a path at glossy surface s seen from v: the BRDF-sampled direction, its
// density and f cos θ / p (zero when the sample is lost below the surface).
struct GlossyStep {
  Vec3 l;
  double pdf = 0;
  Rgb weight;
};

GlossyStep glossy_step(PathContext& ctx, const SurfaceHit& s, Vec3 v) {
  const double u0 = ctx.rng.next_double(), u1 = ctx.rng.next_double(), u2 = ctx.rng.next_double();
  const BrdfSample b = sample_metallic_roughness(*s.glossy, s.normal, v, u0, u1, u2);
  const double cos_l = dot(b.l, s.normal);
  if (b.pdf <= 0 || cos_l <= 0) return {};
  return {b.l, b.pdf, metallic_roughness_brdf(*s.glossy, s.normal, b.l, v) * (cos_l / b.pdf)};
}

// What a ray drawn by BRDF sampling (density pdf) that met no surface brings from outside.
// With `arrival` (how the path reached the glossy point the ray left), the sun disc's part is
// weighted against the mirror lobe at the point before it.
Rgb escaped(PathContext& ctx, const Ray& ray, double pdf, const MirrorArrival& arrival = {}) {
  if (ctx.ref.portals.portals.empty()) return {};
  const ExteriorView view{ctx.ref.mesh, ctx.ref.traced, ctx.ref.portals};
  return escaped_radiance(view, ray, pdf, ctx.rng, ctx.rays, sun_weights(ctx.ref.portals, arrival));
}

Vec3 cosine_direction(Vec3 n, Pcg32& rng) {
  const double u1 = rng.next_double(), u2 = rng.next_double();
  return frame_from_normal(n).to_world(sample_cosine_hemisphere(u1, u2));
}

// Cone samples of a sun at a near-mirror point found by the lobe about its image: its lobe is
// as narrow as the disc, so a few (each a pair) keep the estimate's noise down.
constexpr int kSunSamplesAtMirror = 8;

double mirror_alpha(const ReferenceScene& ref, const MirrorPlane& plane) {
  const double r = ref.glossy.at(static_cast<std::size_t>(plane.group)).roughness;
  return std::max(r * r, 1e-4);  // as the BRDF clamps it
}

// A direction drawn from `lobe` (about a light's image in plane k, seen from `origin` on a
// surface of normal n) that meets the plane's glossy triangles: where, which way, and what the
// light found there counts with at x — cos θ_x / q, weighted against the cosine sampling.
struct ImageSample {
  SurfaceHit hit;
  Vec3 w;
  double weight = 0;
};

std::optional<ImageSample> sample_image(PathContext& ctx, const std::optional<MirrorLobe>& lobe,
                                        Vec3 origin, Vec3 n, std::size_t k) {
  if (!lobe) return std::nullopt;
  const double u1 = ctx.rng.next_double(), u2 = ctx.rng.next_double();
  const Vec3 w = sample_mirror_lobe(*lobe, u1, u2);
  const double cos_x = dot(n, w);
  if (cos_x <= 0) return std::nullopt;
  ImageSample out{{}, w, 0};
  if (!trace_surface(ctx, {origin, w}, out.hit) || out.hit.mirror != static_cast<std::int32_t>(k) ||
      !out.hit.glossy) {
    return std::nullopt;
  }
  const double q = mirror_lobe_pdf(*lobe, w);
  out.weight = cos_x / q * power_heuristic(q, cos_x / kPi);
  return out;
}

// The luminaires' and suns' light reflected by the near-mirror planes onto a surface point,
// sampled about each one's image (reference/reference_mirror.h) and weighted against the cosine
// sampling of the path's continuation from the point.
Rgb mirror_illuminance(PathContext& ctx, Vec3 p, Vec3 n) {
  const ReferenceScene& ref = ctx.ref;
  if (ref.mirror_planes.empty()) return {};
  const Vec3 origin = offset_from_surface(p, n);
  const ExteriorView view{ref.mesh, ref.traced, ref.portals};
  Rgb e;
  for (std::size_t k = 0; k < ref.mirror_planes.size(); ++k) {
    const MirrorPlane& plane = ref.mirror_planes[k];
    const double alpha = mirror_alpha(ref, plane);
    for (std::size_t j = 0; j < ref.luminaires.size(); ++j) {
      const std::optional<ImageSample> m = sample_image(
          ctx, mirror_lobe(plane, alpha, origin, ref.luminaires[j].position), origin, n, k);
      if (!m) continue;
      const SurfaceHit& y = m->hit;
      Vec3 l;
      const Rgb light =
          luminaire_light(ctx, j, offset_from_surface(y.position, y.normal), y.normal, l);
      if (max_component(light) <= 0) continue;
      e += metallic_roughness_brdf(*y.glossy, y.normal, l, -m->w) * light * m->weight;
    }
    // The suns behind clear glass. At y the disc is integrated by cone samples alone (no BRDF
    // sample competes: the cosine strategy's own BRDF continuation takes its weight at x's
    // side).
    for (std::size_t q = 0; q < ref.portals.portals.size(); ++q) {
      const ReferencePortal& portal = ref.portals.portals[q];
      const std::optional<SunDisc>& sun = portal.environment.sun();
      if (!sun || portal.spreads_sun()) continue;
      const std::optional<ImageSample> m = sample_image(
          ctx, mirror_sun_lobe(plane, alpha, origin, sun->direction, sun->angular_radius), origin,
          n, k);
      if (!m) continue;
      const SurfaceHit& y = m->hit;
      const Vec3 at_y = offset_from_surface(y.position, y.normal);
      const NextEventWeight reflect{&*y.glossy, y.normal, -m->w, false};
      Rgb l;
      for (int i = 0; i < kSunSamplesAtMirror; ++i) {
        l += portal_sun_illuminance(view, q, at_y, y.normal, ctx.rng, ctx.rays, reflect);
      }
      e += l * (m->weight / kSunSamplesAtMirror);
    }
  }
  return e;
}

// How a path continues from a surface point: by BRDF sampling at a glossy surface with density
// `brdf_pdf` > 0 (light it finds through a window counts with the BRDF strategy's weight), or
// (brdf_pdf = 0) cosine-distributed about `normal`.
struct Continuation {
  double brdf_pdf = 0;
  Vec3 normal;
};

// Luminance arriving at `origin` from direction `dir` (light reflected by the scene), drawn
// as `how` says.
Rgb incident_luminance(PathContext& ctx, Vec3 origin, Vec3 dir, Continuation how) {
  Rgb result, throughput{1, 1, 1};
  Ray ray{origin, dir};
  double pdf = how.brdf_pdf;
  Vec3 from_normal = how.normal;
  MirrorArrival arrival;  // how the path reached the last glossy point
  for (int depth = 0; depth < ctx.max_depth; ++depth) {
    SurfaceHit s;
    if (!trace_surface(ctx, ray, s)) {
      if (pdf > 0) result += throughput * escaped(ctx, ray, pdf, arrival);
      // The top-level environment: a glossy continuation's density, or the cosine density.
      result += throughput *
                open_escape(ctx, ray,
                            pdf > 0 ? pdf : std::max(0.0, dot(from_normal, ray.direction)) / kPi);
      break;
    }
    if (depth >= ctx.hits) break;  // --max-bounces: no more reflections
    arrival = {};
    if (s.glossy) {
      // L = Σ next events (weighted) + f cos / p · L_in(l'), l' by BRDF sampling.
      const Vec3 v = -ray.direction;
      if (pdf == 0 && s.mirror >= 0) {  // reached by cosine sampling
        const MirrorPlane& plane = ctx.ref.mirror_planes[static_cast<std::size_t>(s.mirror)];
        arrival = {&plane, mirror_alpha(ctx.ref, plane), ray.origin, ray.direction,
                   std::max(0.0, dot(from_normal, ray.direction)) / kPi};
      }
      result += throughput * glossy_next_events(ctx, s, v, arrival);
      const GlossyStep step = glossy_step(ctx, s, v);
      const double survive = std::min(1.0, max_component(step.weight));
      if (survive <= 0 || ctx.rng.next_double() >= survive) break;
      throughput = throughput * step.weight * (1 / survive);
      ray = {offset_from_surface(s.position, s.normal), step.l};
      pdf = step.pdf;
      from_normal = s.normal;
      continue;
    }
    pdf = 0;
    // L = ρ/π E_direct + ρ · L_in(next): next-event estimation (luminaires and the
    // exterior through portals), then continue; a continuation that escapes adds nothing.
    const Rgb e = direct_illuminance(ctx, s.position, s.normal) +
                  daylight_illuminance(ctx, s.position, s.normal) +
                  emitters_illuminance(ctx, s.position, s.normal) +
                  open_illuminance(ctx, s.position, s.normal) +
                  (depth + 1 < ctx.hits ? mirror_illuminance(ctx, s.position, s.normal) : Rgb{});
    result += throughput * lambertian_radiance(s.albedo, e);
    throughput = throughput * s.albedo;
    const double survive = std::min(1.0, max_component(s.albedo));
    if (survive <= 0 || ctx.rng.next_double() >= survive) break;
    throughput *= 1 / survive;
    ray = {offset_from_surface(s.position, s.normal), cosine_direction(s.normal, ctx.rng)};
    from_normal = s.normal;
  }
  return result;
}

// One-sample estimate of the reflected part of E at a front surface point: π · L_in(ω),
// ω cosine-distributed about n, and the near-mirrors' reflection of the luminaires sampled
// about their images.
Rgb indirect_sample(PathContext& ctx, Vec3 p, Vec3 n) {
  return incident_luminance(ctx, offset_from_surface(p, n), cosine_direction(n, ctx.rng), {0, n}) *
             kPi +
         (ctx.hits >= 1 ? mirror_illuminance(ctx, p, n) : Rgb{});
}

}  // namespace

ReferenceScene make_reference_scene(const Scene& scene, const PreparedMesh& mesh,
                                    const TracedScene& traced,
                                    const std::vector<PlacedLuminaire>& luminaires,
                                    std::vector<Environment> environments, PlacedEmitters emitters,
                                    const std::vector<std::vector<ExteriorObject>>& exterior) {
  ReferenceScene ref{mesh, traced, luminaires, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  ref.emitters = make_reference_emitters(std::move(emitters));
  ref.portals = make_reference_portals(scene, mesh, std::move(environments), exterior);
  for (std::size_t j = 0; j < luminaires.size(); ++j) {
    const Luminaire& l = scene.luminaires.at(j);
    const LuminousOpening o = luminaires[j].distribution.opening();
    ReferenceOpening opening{
        o.length_m, o.width_m, o.height_m,
        o.shape == OpeningShape::kCircular || o.shape == OpeningShape::kEllipse ||
            o.shape == OpeningShape::kVerticalCylinder ||
            o.shape == OpeningShape::kVerticalEllipticalCylinder ||
            o.shape == OpeningShape::kSphere || o.shape == OpeningShape::kEllipsoidalSpheroid};
    if (o.shape == OpeningShape::kPoint) opening = {};
    if (l.has_size) opening = {l.size.y, l.size.x, l.size.z, false};  // scene size: a box
    ref.openings.push_back(opening);
  }
  ref.triangle_albedo.reserve(mesh.triangles.size());
  GlossyMaterials glossy = glossy_materials(scene.materials);
  for (std::uint32_t m : mesh.triangle_material) {
    ref.triangle_albedo.push_back(scene.materials.at(m).albedo);
    ref.triangle_glossy.push_back(glossy.index.at(m));
  }
  ref.glossy = std::move(glossy.brdf);
  std::vector<std::uint32_t> ids(mesh.triangles.size());
  for (std::size_t t = 0; t < ids.size(); ++t) ids[t] = static_cast<std::uint32_t>(t);
  ref.mirror_planes = find_mirror_planes(mesh.positions, mesh.triangles, ids, [&](std::size_t t) {
    const std::int32_t g = ref.triangle_glossy[t];
    return g >= 0 && reflects_as_mirror(ref.glossy[static_cast<std::size_t>(g)]) ? std::int64_t{g}
                                                                                 : std::int64_t{-1};
  });
  ref.triangle_mirror = mirror_plane_of(ref.mirror_planes, mesh.triangles.size());
  return ref;
}

void light_with_environment(ReferenceScene& ref, Environment environment) {
  ref.open_sampler.emplace(environment);
  ref.open_environment = std::move(environment);
}

std::vector<Rgb> reference_sensor_illuminance(const Scene& scene, const ReferenceScene& ref,
                                              const ReferenceSettings& settings,
                                              ReferenceStats* stats) {
  struct Point {
    Vec3 p, n;
  };
  std::vector<Point> points;
  for (const SensorSet& s : scene.sensors) {
    for (const Vec3& p : s.points) points.push_back({p, s.normal});
  }
  std::vector<Rgb> result(points.size());
  std::atomic<std::uint64_t> rays{0};
  Progress progress("reference sensors", points.size(), settings.progress);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size()), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      PathContext ctx = path_context(ref, settings, i);
      // Point sources once (exact); luminaires with an opening, daylight and the reflected
      // light averaged over the samples.
      const Rgb direct = direct_illuminance(ctx, points[i].p, points[i].n, Sources::kPoints);
      Rgb sampled;
      for (int s = 0; s < settings.spp; ++s) {
        sampled += direct_illuminance(ctx, points[i].p, points[i].n, Sources::kOpenings) +
                   daylight_illuminance(ctx, points[i].p, points[i].n) +
                   emitters_illuminance(ctx, points[i].p, points[i].n) +
                   open_illuminance(ctx, points[i].p, points[i].n) +
                   indirect_sample(ctx, points[i].p, points[i].n);
      }
      result[i] = direct + sampled / settings.spp;
      rays += ctx.rays;
      progress.advance();
    }
  });
  progress.finish();
  if (stats) *stats = {rays.load(), progress.seconds()};
  return result;
}

ReferenceImages reference_render(const PinholeCamera& camera, const ReferenceScene& ref,
                                 const ReferenceSettings& settings, ReferenceStats* stats) {
  const int w = camera.width, h = camera.height;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ReferenceImages out{{w, h, std::vector<Rgb>(static_cast<std::size_t>(w) * h)},
                      {w, h, std::vector<Rgb>(static_cast<std::size_t>(w) * h)}};
  // Sensor streams use indices below 2^40; pixel streams start above, so a pixel never
  // repeats a sensor's random sequence.
  constexpr std::uint64_t kPixelStreams = std::uint64_t{1} << 40;
  const ExteriorView view{ref.mesh, ref.traced, ref.portals};
  std::atomic<std::uint64_t> rays{0};
  std::atomic<std::size_t> back_side_pixels{0};
  Progress progress("reference image", static_cast<std::uint64_t>(h), settings.progress);
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t index = static_cast<std::size_t>(y) * w + x;
        PathContext ctx = path_context(ref, settings, kPixelStreams + index);
        Rgb e_sum, l_sum;
        int covered = 0, exterior = 0, back_sides = 0;
        for (int s = 0; s < settings.spp; ++s) {
          const double jx = ctx.rng.next_double(), jy = ctx.rng.next_double();
          const Ray ray{camera.eye, normalize(camera.direction(x + jx, y + jy))};
          SurfaceHit hit;
          bool back_side = false;
          if (!trace_surface(ctx, ray, hit, &back_side)) {
            if (back_side) {  // the back of a surface, nearer than any window: black
              ++back_sides;
              continue;
            }
            // Looking out through a portal: the environment, sun disc included.
            const std::int32_t p = escape_portal(view, ray, ctx.rays);
            if (p == kNoPortal) {
              // Or out of the scene: the top-level environment.
              if (ref.open_environment && leaves_scene(ctx, ray)) {
                l_sum += ref.open_environment->radiance(ray.direction);
                ++exterior;
              }
              continue;
            }
            const ReferencePortal& portal = ref.portals.portals[static_cast<std::size_t>(p)];
            l_sum += through_glass(portal, ray.origin, ray.direction, true, ctx.rng, ctx.rays);
            ++exterior;
            continue;
          }
          const Rgb e = direct_illuminance(ctx, hit.position, hit.normal) +
                        daylight_illuminance(ctx, hit.position, hit.normal) +
                        emitters_illuminance(ctx, hit.position, hit.normal) +
                        open_illuminance(ctx, hit.position, hit.normal) +
                        indirect_sample(ctx, hit.position, hit.normal);
          e_sum += e;
          if (hit.glossy) {
            // Toward the eye: next events and one BRDF-sampled continuation.
            const Vec3 v = -ray.direction;
            l_sum += glossy_next_events(ctx, hit, v);
            const GlossyStep step = glossy_step(ctx, hit, v);
            if (step.pdf > 0) {
              l_sum += step.weight *
                       incident_luminance(ctx, offset_from_surface(hit.position, hit.normal),
                                          step.l, {step.pdf, hit.normal});
            }
          } else {
            l_sum += lambertian_radiance(hit.albedo, e);
          }
          ++covered;
        }
        // Pixels partly covering the background average over all samples (black there);
        // illuminance is that of the surfaces seen.
        out.luminance.pixels[index] =
            covered + exterior + back_sides == 0 ? Rgb{nan, nan, nan} : l_sum / settings.spp;
        out.illuminance.pixels[index] = covered == 0 ? Rgb{nan, nan, nan} : e_sum / covered;
        if (back_sides == settings.spp) ++back_side_pixels;
        rays += ctx.rays;
      }
      progress.advance();
    }
  });
  progress.finish();
  if (stats) *stats = {rays.load(), progress.seconds()};
  out.back_side_pixels = back_side_pixels.load();
  return out;
}

}  // namespace relight
