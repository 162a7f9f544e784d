#include "sources/objects/object_transfer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/frame.h"
#include "math/sampling.h"

namespace relight {

namespace {

constexpr std::size_t kChunk = 256;  // rows traced by one task
constexpr std::uint64_t kConeSeed = 0x6f626a636f6e6573ULL;
constexpr std::uint64_t kObjectSeed = 0x6f626a726f777321ULL;
// A row weight this small changes nothing: what a ray added and a later update took off again.
constexpr float kNegligible = 1e-9f;

// A row size that says the row is as it was (update_cone_row; replace_rows keeps it).
constexpr std::uint32_t kUnchanged = ~std::uint32_t{0};
constexpr std::size_t kUnchangedRow = ~std::size_t{0};

// One chunk of rows while it is traced.
struct Chunk {
  std::vector<std::uint32_t> row_sizes;  // or kUnchanged
  std::vector<std::uint32_t> columns;
  std::vector<float> values;
  std::vector<GlassHit> glass;
  std::uint64_t rays = 0;
};

// A row's entries before merging equal columns.
struct RowScratch {
  std::vector<std::pair<std::uint32_t, float>> entries;
  void add(std::uint32_t column, double weight) {
    if (weight != 0) entries.emplace_back(column, static_cast<float>(weight));
  }
  // Sorts, merges and appends the row to `chunk`, added to a row given sorted by column
  // (`columns`, `values`: a previous row being updated; empty for a new row).
  void flush(Chunk& chunk, std::span<const std::uint32_t> columns = {},
             std::span<const float> values = {}) {
    std::sort(entries.begin(), entries.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::uint32_t count = 0;
    std::size_t i = 0, j = 0;
    while (i < entries.size() || j < columns.size()) {
      const std::uint32_t column =
          std::min(i < entries.size() ? entries[i].first : ~std::uint32_t{0},
                   j < columns.size() ? columns[j] : ~std::uint32_t{0});
      float sum = 0;
      for (; j < columns.size() && columns[j] == column; ++j) sum += values[j];
      for (; i < entries.size() && entries[i].first == column; ++i) sum += entries[i].second;
      if (std::abs(sum) <= kNegligible) continue;  // what a ray added and took off again
      chunk.columns.push_back(column);
      chunk.values.push_back(sum);
      ++count;
    }
    chunk.row_sizes.push_back(count);
    entries.clear();
  }
};

// What a ray from a point meets first.
struct FirstHit {
  enum Kind { kNothing, kRoom, kGlass, kObject } kind = kNothing;
  RayHit hit;
};

bool faces(const std::vector<Vec3>& positions, const Triangle& t, Vec3 direction) {
  const Vec3 a = positions[t[0]];
  return dot(cross(positions[t[1]] - a, positions[t[2]] - a), direction) < 0;
}

// The room's first surface along `ray` (opaque or glass), as the stored G sees it.
FirstHit room_hit(const RuntimeScene& room, const Ray& ray) {
  FirstHit out;
  const RayHit opaque = room.occluders().intersect(ray);
  const RayHit glass = room.glass().triangle_count() > 0
                           ? room.glass().intersect({ray.origin, ray.direction, ray.t_near,
                                                     opaque.hit() ? opaque.t : ray.t_far})
                           : RayHit{};
  if (glass.hit()) return {FirstHit::kGlass, glass};
  if (opaque.hit()) return {FirstHit::kRoom, opaque};
  return out;
}

// Adds ±weight spread over the hit's vertices (front sides only: back sides absorb, as in G),
// or a glass hit.
void add_hit(const RuntimeScene& room, const PlacedObjects& objects, const FirstHit& h,
             const Ray& ray, double weight, std::uint32_t row, RowScratch& scratch, Chunk& chunk) {
  const double b[3] = {1 - h.hit.u - h.hit.v, h.hit.u, h.hit.v};
  switch (h.kind) {
    case FirstHit::kRoom: {
      const Triangle& t = room.opaque_triangle(h.hit.triangle);
      if (!faces(room.mesh_positions(), t, ray.direction)) return;
      for (int k = 0; k < 3; ++k) scratch.add(t[k], weight * b[k]);
      return;
    }
    case FirstHit::kObject: {
      const Triangle& t = objects.triangles[h.hit.triangle];
      if (!faces(objects.positions, t, ray.direction)) return;
      const auto base = static_cast<std::uint32_t>(room.vertex_count());
      for (int k = 0; k < 3; ++k) scratch.add(base + t[k], weight * b[k]);
      return;
    }
    case FirstHit::kGlass:
      chunk.glass.push_back({row, h.hit.triangle, ray.direction, static_cast<float>(weight)});
      return;
    case FirstHit::kNothing:
      return;
  }
}

}  // namespace

double sphere_share(Vec3 origin, Vec3 normal, const BoundingSphere& s) {
  if (s.radius <= 0) return 0;
  const Vec3 to_centre = s.centre - origin;
  const double d = length(to_centre);
  if (d <= s.radius) return 1;
  const double sin_alpha = s.radius / d;
  const double omega = 2 * kPi * (1 - std::sqrt(std::max(0.0, 1 - sin_alpha * sin_alpha)));
  return omega / kPi * std::clamp(dot(normal, to_centre / d) + sin_alpha, 0.0, 1.0);
}

namespace {

// Where row `row` gathers from: a room receiver (row < R) or object vertex row − R.
struct Origin {
  Vec3 point, normal;
  std::size_t own = kNone;  // the object the vertex belongs to; kNone for a room receiver
  bool sensor = false;
  static constexpr std::size_t kNone = ~std::size_t{0};
};

Origin origin_of(const RuntimeScene& room, const PlacedObjects& objects, std::size_t row) {
  const std::size_t receivers = room.receivers();
  if (row < receivers) {
    const Vec3 n = room.normal(row);
    return {offset_from_surface(room.ray_point(row), n), n, Origin::kNone,
            row >= room.vertex_count()};
  }
  const std::size_t q = row - receivers;
  const Vec3 n = objects.normals[q];
  return {offset_from_surface(objects.ray_points[q], n), n, objects.object_of_vertex(q), false};
}

// What the base row of `o` saw along `ray`: the room (opaque or glass), and for an object
// vertex its own object too.
FirstHit base_hit(const RuntimeScene& room, const PlacedObjects& objects, const Origin& o,
                  const Ray& ray) {
  FirstHit h = room_hit(room, ray);
  if (o.own != Origin::kNone) {
    const RayHit self = objects.own[o.own].intersect(
        {ray.origin, ray.direction, 0, h.kind != FirstHit::kNothing ? h.hit.t : ray.t_far});
    if (self.hit()) h = {FirstHit::kObject, self};
  }
  return h;
}

// Whether row `row` has rays toward object k: k visible, the origin not on k nor on a hidden
// object, the row not taken from proxies.
bool has_cone_row(const RuntimeScene& room, const PlacedObjects& objects, std::size_t k,
                  std::span<const std::uint8_t> proxied, const Origin& o, std::size_t row) {
  const std::size_t column = ObjectIndexing(room, objects).column(row);
  return objects.visible(k) && o.own != k && (o.own == Origin::kNone || objects.visible(o.own)) &&
         !(column < proxied.size() && proxied[column] != 0);
}

// Where in a cone's frame the rays that may meet a sphere lie: polar angle θ from the axis
// within β of the sphere's direction γ (as the cosine range [cos_min, cos_max]) and azimuth
// within `half_width` of `phi` (sin Δ = sin β / sin γ; every azimuth when the axis is within β
// of it), β the sphere's angular radius from the origin; `all` when the origin is inside.
// Conservative by kWindowMargin, so that rays outside are skipped before their direction is
// computed (the exact test follows for the rest).
struct SphereWindow {
  bool all = false, none = false;
  double cos_min = -1, cos_max = 1, phi = 0, half_width = kPi;
};

constexpr double kWindowMargin = 1e-6;  // rad

SphereWindow sphere_window(const Frame& frame, Vec3 origin, const BoundingSphere& s) {
  SphereWindow w;
  if (s.radius <= 0) {
    w.none = true;
    return w;
  }
  const Vec3 to = s.centre - origin;
  const double d = length(to);
  if (d <= s.radius * (1 + 1e-9)) {
    w.all = true;
    return w;
  }
  const double beta = std::asin(s.radius / d) + kWindowMargin;
  const Vec3 b = frame.to_local(to / d);
  const double gamma = std::acos(std::clamp(b.z, -1.0, 1.0));
  w.cos_max = std::cos(std::max(0.0, gamma - beta));
  w.cos_min = std::cos(std::min(kPi, gamma + beta));
  if (gamma > beta && kPi - gamma > beta) {
    w.phi = std::atan2(b.y, b.x);
    w.half_width = std::asin(std::min(1.0, std::sin(beta) / std::sin(gamma))) + kWindowMargin;
  }
  return w;
}

bool in_window(const SphereWindow& w, double cos_t, double phi) {
  if (w.all) return true;
  if (w.none || cos_t < w.cos_min - 1e-12 || cos_t > w.cos_max + 1e-12) return false;
  if (w.half_width >= kPi) return true;
  double gap = std::fmod(std::abs(phi - w.phi), 2 * kPi);
  gap = std::min(gap, 2 * kPi - gap);
  return gap <= w.half_width;
}

// Whether the ray from `origin` along unit `dir` meets one of `spheres`.
bool meets_any(Vec3 origin, Vec3 dir, std::span<const BoundingSphere> spheres) {
  return std::any_of(spheres.begin(), spheres.end(), [&](const BoundingSphere& s) {
    return s.radius > 0 && ray_near_sphere(origin, dir, s, 0);
  });
}

// Calls visit(direction, weight) for each ray of row `row` toward object k's sphere `s`: rays
// uniformly over the sphere's cone (cosine-distributed over the hemisphere from inside it),
// weight Ω/N · cos θ / π, as many as the sphere's share asks; none below the cull. The same
// rays every time for the same row, object and sphere. With `only`, just the rays that meet
// one of those spheres (the others skipped before their direction is made).
template <typename Visit>
void for_each_cone_ray(const ObjectTransferSettings& settings, const Origin& o,
                       const BoundingSphere& s, std::size_t k, std::size_t row, Visit&& visit,
                       std::span<const BoundingSphere> only = {}) {
  const Vec3 to_centre = s.centre - o.point;
  const double d = length(to_centre);
  const bool inside = d <= s.radius;
  const double share = sphere_share(o.point, o.normal, s);
  if (!inside && share < settings.cull) return;
  double cos_alpha = -1, omega = 2 * kPi;  // inside: the whole hemisphere (cosine-sampled)
  Vec3 axis = o.normal;
  if (!inside) {
    const double sin_alpha = s.radius / d;
    cos_alpha = std::sqrt(std::max(0.0, 1 - sin_alpha * sin_alpha));
    axis = to_centre / d;
    omega = 2 * kPi * (1 - cos_alpha);
  }
  // A sensor's reading is its own row, not smoothed between vertices: it gets more rays.
  const int scale = o.sensor ? settings.sensor_ray_factor : 1;
  const int rays =
      scale *
      (inside ? settings.cone_rays_max
              : std::clamp(static_cast<int>(std::ceil(share * settings.cone_rays_per_hemisphere)),
                           settings.cone_rays_min, settings.cone_rays_max));
  Pcg32 rng(kConeSeed + k, row);
  const std::uint32_t s1 = rng.next_u32(), s2 = rng.next_u32();
  const Frame frame = frame_from_normal(axis);
  constexpr std::size_t kMaxWindows = 32;
  std::array<SphereWindow, kMaxWindows> windows;
  const std::size_t window_count = only.size() > kMaxWindows ? 0 : only.size();
  for (std::size_t i = 0; i < window_count; ++i) {
    windows[i] = sphere_window(frame, o.point, only[i]);
  }
  for (int i = 0; i < rays; ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    const double u1 = unit_interval(van_der_corput(index, s1));
    const double u2 = unit_interval(sobol2(index, s2));
    // The ray's polar angle about the frame's axis and its azimuth (sample_cosine_hemisphere's
    // mapping inside the sphere).
    const double cos_t = inside ? std::sqrt(std::max(0.0, 1 - u1)) : 1 - u1 * (1 - cos_alpha);
    const double phi = 2 * kPi * u2;
    if (window_count > 0 &&
        std::none_of(windows.begin(), windows.begin() + window_count,
                     [&](const SphereWindow& w) { return in_window(w, cos_t, phi); })) {
      continue;
    }
    if (inside) {
      const Vec3 dir = frame.to_world(sample_cosine_hemisphere(u1, u2));
      if (only.empty() || meets_any(o.point, dir, only)) visit(dir, 1.0 / rays);
      continue;
    }
    const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
    const Vec3 dir = frame.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t});
    if (!only.empty() && !meets_any(o.point, dir, only)) continue;
    const double weight = omega / rays * std::max(0.0, dot(o.normal, dir)) / kPi;
    if (weight > 0) visit(dir, weight);
  }
}

// One ray of a cone row toward object k among `objects` as placed: counted only for the first
// object it meets (the partition among overlapping cones; a vertex's own object is its base
// row's) when that object is k and no room surface hides it: +weight on what it sees of k,
// −weight on what the base row saw there.
void add_cone_ray(const RuntimeScene& room, const PlacedObjects& objects, const Origin& o,
                  std::size_t k, Vec3 dir, double weight, std::uint32_t row, RowScratch& scratch,
                  Chunk& chunk) {
  ++chunk.rays;
  const Ray ray{o.point, dir};
  const RayHit object = objects.tracer.intersect(ray);
  if (!object.hit() || objects.triangle_object[object.triangle] != k) return;
  const FirstHit before = base_hit(room, objects, o, ray);
  chunk.rays += 2;
  if (before.kind != FirstHit::kNothing && before.hit.t <= object.t) return;  // hidden
  add_hit(room, objects, {FirstHit::kObject, object}, ray, weight, row, scratch, chunk);
  add_hit(room, objects, before, ray, -weight, row, scratch, chunk);
}

// One ray of unmoved object k's cone row that may meet a moved object: what changed in
// add_cone_ray's count of it between `before` and `objects`. k did not move, so its hit and
// what the base row saw behind it are the same then and now; only whether k is the first
// object along the ray may differ. One ray against k alone (a miss: counted neither then nor
// now), then one against each placement up to k's hit, and the room only when that changed.
void update_cone_ray(const RuntimeScene& room, const PlacedObjects& objects,
                     const PlacedObjects& before, const Origin& o, std::size_t k, Vec3 dir,
                     double weight, std::uint32_t row, RowScratch& scratch, Chunk& chunk) {
  chunk.rays += 3;
  const Ray ray{o.point, dir};
  const RayHit hit = objects.own[k].intersect(ray);
  if (!hit.hit()) return;
  const auto k_first = [&](const PlacedObjects& placed) {
    const RayHit h = placed.tracer.intersect({ray.origin, ray.direction, 0, hit.t});
    return !h.hit() || placed.triangle_object[h.triangle] == k;
  };
  const bool now = k_first(objects);
  if (now == k_first(before)) return;
  const FirstHit behind = base_hit(room, objects, o, ray);
  chunk.rays += 2;
  if (behind.kind != FirstHit::kNothing && behind.hit.t <= hit.t) return;  // the room hides k
  const double w = now ? weight : -weight;
  add_hit(room, objects, {FirstHit::kObject, hit}, ray, w, row, scratch, chunk);
  add_hit(room, objects, behind, ray, -w, row, scratch, chunk);
}

// Row `row` of object k's cone rows, traced whole; rows of vertices that take their row from
// proxies stay empty.
void trace_cone_row(const RuntimeScene& room, const PlacedObjects& objects,
                    const ObjectTransferSettings& settings, std::size_t k,
                    std::span<const std::uint8_t> proxied, std::size_t row, RowScratch& scratch,
                    Chunk& chunk) {
  const Origin o = origin_of(room, objects, row);
  if (has_cone_row(room, objects, k, proxied, o, row)) {
    for_each_cone_ray(settings, o, objects.bounds[k], k, row, [&](Vec3 dir, double weight) {
      add_cone_ray(room, objects, o, k, dir, weight, static_cast<std::uint32_t>(row), scratch,
                   chunk);
    });
  }
  scratch.flush(chunk);
}

// Row `row` of unmoved object k's cone rows, from an origin that did not move, after objects
// moved from their places in `before` (spheres `changed`: where they were and where they are
// now): the rays that meet none of `changed` see what they saw before, so only the others are
// traced (update_cone_ray: what changed in their count, added to the row `previous`). Glass
// hits of equal portal and direction are merged.
void update_cone_row(const RuntimeScene& room, const PlacedObjects& objects,
                     const PlacedObjects& before, const ObjectTransferSettings& settings,
                     std::size_t k, std::span<const std::uint8_t> proxied,
                     std::span<const BoundingSphere> changed, const ObjectRows& previous,
                     std::size_t row, RowScratch& scratch, Chunk& chunk) {
  const std::size_t glass_from = chunk.glass.size();
  const auto lo = std::partition_point(previous.glass.begin(), previous.glass.end(),
                                       [&](const GlassHit& g) { return g.row < row; });
  const auto hi = std::partition_point(lo, previous.glass.end(),
                                       [&](const GlassHit& g) { return g.row <= row; });
  chunk.glass.insert(chunk.glass.end(), lo, hi);
  const std::size_t glass_kept = chunk.glass.size();
  const Origin o = origin_of(room, objects, row);
  if (has_cone_row(room, objects, k, proxied, o, row)) {
    const auto out_row = static_cast<std::uint32_t>(row);
    for_each_cone_ray(
        settings, o, objects.bounds[k], k, row,
        [&](Vec3 dir, double weight) {
          update_cone_ray(room, objects, before, o, k, dir, weight, out_row, scratch, chunk);
        },
        changed);
  }
  if (scratch.entries.empty() && chunk.glass.size() == glass_kept) {  // no ray's count changed
    chunk.glass.resize(glass_from);
    chunk.row_sizes.push_back(kUnchanged);
    return;
  }
  // Merge this row's glass hits along the same direction through the same portal.
  std::vector<GlassHit> merged;
  for (std::size_t i = glass_from; i < chunk.glass.size(); ++i) {
    const GlassHit& g = chunk.glass[i];
    auto same = std::find_if(merged.begin(), merged.end(), [&](const GlassHit& m) {
      return m.portal == g.portal && m.direction.x == g.direction.x &&
             m.direction.y == g.direction.y && m.direction.z == g.direction.z;
    });
    if (same == merged.end()) {
      merged.push_back(g);
    } else {
      same->weight += g.weight;
    }
  }
  chunk.glass.resize(glass_from);
  for (const GlassHit& g : merged) {
    if (std::abs(g.weight) > kNegligible) chunk.glass.push_back(g);
  }
  const std::size_t from = previous.begin[row], size = previous.end[row] - from;
  scratch.flush(chunk, std::span(previous.columns).subspan(from, size),
                std::span(previous.values).subspan(from, size));
}

// The base row of object vertex q: cosine-distributed rays against the room and its own object.
void trace_base_row(const RuntimeScene& room, const PlacedObjects& objects,
                    const ObjectTransferSettings& settings, const ReceiverProxies& proxies,
                    std::size_t q, RowScratch& scratch, Chunk& chunk) {
  const Origin o = origin_of(room, objects, room.receivers() + q);
  // A hidden object gathers nothing; a vertex that is not a proxy takes its proxies' rows.
  if (!objects.visible(o.own) || proxies.proxy_of[room.vertex_count() + q] < 0) {
    scratch.flush(chunk);
    return;
  }
  Pcg32 rng(kObjectSeed, q);
  const std::uint32_t s1 = rng.next_u32(), s2 = rng.next_u32();
  const Frame frame = frame_from_normal(o.normal);
  const int rays = settings.object_rays;
  const double weight = 1.0 / rays;
  for (int i = 0; i < rays; ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    const Vec3 dir = frame.to_world(sample_cosine_hemisphere(
        unit_interval(van_der_corput(index, s1)), unit_interval(sobol2(index, s2))));
    const Ray ray{o.point, dir};
    chunk.rays += 2;
    add_hit(room, objects, base_hit(room, objects, o, ray), ray, weight,
            static_cast<std::uint32_t>(q), scratch, chunk);
  }
  scratch.flush(chunk);
}

// Traces rows `rows` (or [0, count) when `rows` is null) in chunks and joins them in that order.
// With `by_index`, trace_row gets the index into `rows` instead of the row.
template <typename TraceRow>
ObjectRows trace_rows(std::size_t count, const std::vector<std::uint32_t>* rows,
                      const TraceRow& trace_row, std::uint64_t& rays, bool by_index = false) {
  if (rows != nullptr) count = rows->size();
  std::vector<Chunk> chunks((count + kChunk - 1) / kChunk);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size()), [&](const auto& range) {
    RowScratch scratch;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      const std::size_t end = std::min(count, (c + 1) * kChunk);
      for (std::size_t i = c * kChunk; i < end; ++i) {
        trace_row(rows != nullptr && !by_index ? (*rows)[i] : i, scratch, chunks[c]);
      }
    }
  });
  ObjectRows out;
  std::size_t entries = 0, glass = 0;
  for (const Chunk& c : chunks) {
    entries += c.columns.size();
    glass += c.glass.size();
  }
  out.begin.reserve(count);
  out.end.reserve(count);
  out.columns.reserve(entries);
  out.values.reserve(entries);
  out.glass.reserve(glass);
  out.used = entries;
  std::size_t next = 0;
  for (const Chunk& c : chunks) {
    for (const std::uint32_t size : c.row_sizes) {
      if (size == kUnchanged) {
        out.begin.push_back(kUnchangedRow);
        out.end.push_back(kUnchangedRow);
        continue;
      }
      out.begin.push_back(next);
      out.end.push_back(next += size);
    }
    out.columns.insert(out.columns.end(), c.columns.begin(), c.columns.end());
    out.values.insert(out.values.end(), c.values.begin(), c.values.end());
    out.glass.insert(out.glass.end(), c.glass.begin(), c.glass.end());
    rays += c.rays;
  }
  return out;
}

// The rows listed in `redo` (ascending) replaced by those of `traced` (in the order of
// `redo`; kUnchangedRow: kept), their entries appended; glass hits likewise. Packs the rows again
// when as many entries are unused as used.
void replace_rows(ObjectRows& rows, const std::vector<std::uint32_t>& redo, ObjectRows traced) {
  const std::size_t offset = rows.columns.size();
  rows.columns.insert(rows.columns.end(), traced.columns.begin(), traced.columns.end());
  rows.values.insert(rows.values.end(), traced.values.begin(), traced.values.end());
  for (std::size_t i = 0; i < redo.size(); ++i) {
    const std::size_t r = redo[i];
    if (traced.begin[i] == kUnchangedRow) continue;
    rows.used += traced.end[i] - traced.begin[i];
    rows.used -= rows.end[r] - rows.begin[r];
    rows.begin[r] = offset + traced.begin[i];
    rows.end[r] = offset + traced.end[i];
  }
  if (rows.columns.size() > 2 * rows.used + 4096) {
    ObjectRows packed;
    packed.columns.reserve(rows.used);
    packed.values.reserve(rows.used);
    for (std::size_t r = 0; r < rows.rows(); ++r) {
      const auto lo = static_cast<std::ptrdiff_t>(rows.begin[r]);
      const auto hi = static_cast<std::ptrdiff_t>(rows.end[r]);
      packed.begin.push_back(packed.columns.size());
      packed.columns.insert(packed.columns.end(), rows.columns.begin() + lo,
                            rows.columns.begin() + hi);
      packed.values.insert(packed.values.end(), rows.values.begin() + lo, rows.values.begin() + hi);
      packed.end.push_back(packed.columns.size());
    }
    rows.begin = std::move(packed.begin);
    rows.end = std::move(packed.end);
    rows.columns = std::move(packed.columns);
    rows.values = std::move(packed.values);
  }
  // Glass hits stay sorted by row (update_cone_row looks a row's up).
  if (rows.glass.empty() && traced.glass.empty()) return;
  std::vector<bool> again(rows.rows(), false);
  for (std::size_t i = 0; i < redo.size(); ++i) again[redo[i]] = traced.begin[i] != kUnchangedRow;
  std::vector<GlassHit> kept;
  for (const GlassHit& g : rows.glass) {
    if (!again[g.row]) kept.push_back(g);
  }
  rows.glass.clear();
  std::merge(kept.begin(), kept.end(), traced.glass.begin(), traced.glass.end(),
             std::back_inserter(rows.glass),
             [](const GlassHit& a, const GlassHit& b) { return a.row < b.row; });
}

// Whether the cone from `o` toward sphere a may meet sphere b (they overlap as seen from o).
bool cones_overlap(Vec3 o, const BoundingSphere& a, const BoundingSphere& b) {
  if (a.radius <= 0 || b.radius <= 0) return false;
  const Vec3 da = a.centre - o, db = b.centre - o;
  const double la = length(da), lb = length(db);
  if (la <= a.radius || lb <= b.radius) return true;
  // The angle between the axes at most the sum of the half-angles (each below 90°), compared
  // as cosines: cos(α_a + α_b) = cos α_a cos α_b − sin α_a sin α_b.
  const double sa = a.radius / la, sb = b.radius / lb;
  const double ca = std::sqrt(1 - sa * sa), cb = std::sqrt(1 - sb * sb);
  return dot(da, db) / (la * lb) >= ca * cb - sa * sb - 1e-12;
}

Vec3 column_point(const RuntimeScene& room, const PlacedObjects& objects, std::size_t column) {
  const std::size_t v = room.vertex_count();
  return column < v ? room.ray_point(column) : objects.ray_points[column - v];
}

// Which vertices (unified columns [lo, hi)) take their row toward object k from proxies, as
// placed now.
void mark_proxied(const RuntimeScene& room, const PlacedObjects& objects,
                  const ObjectTransferSettings& settings, const ReceiverProxies& proxies,
                  std::size_t k, std::size_t lo, std::size_t hi, std::vector<std::uint8_t>& out) {
  out.resize(room.vertex_count() + objects.vertex_count(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(lo, hi, 4096), [&](const auto& range) {
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      out[c] = takes_proxy_row(proxies, c, column_point(room, objects, c), objects.bounds[k],
                               settings.proxy_distance)
                   ? 1
                   : 0;
    }
  });
}

ObjectRows trace_cones(const RuntimeScene& room, const PlacedObjects& objects,
                       const ObjectTransferSettings& settings, std::size_t k,
                       std::span<const std::uint8_t> proxied,
                       const std::vector<std::uint32_t>* rows, std::uint64_t& rays) {
  return trace_rows(
      room.receivers() + objects.vertex_count(), rows,
      [&](std::size_t row, RowScratch& scratch, Chunk& chunk) {
        trace_cone_row(room, objects, settings, k, proxied, row, scratch, chunk);
      },
      rays);
}

}  // namespace

ObjectTransfer trace_object_transfer(const RuntimeScene& room, const PlacedObjects& objects,
                                     const ObjectTransferSettings& settings) {
  ObjectTransfer t;
  const std::size_t rows = room.receivers() + objects.vertex_count();
  const std::size_t columns = room.vertex_count() + objects.vertex_count();
  std::vector<Vec3> points, normals;
  std::vector<std::uint32_t> group;  // 0: the room; k + 1: object k
  for (std::size_t c = 0; c < columns; ++c) {
    const bool in_room = c < room.vertex_count();
    const std::size_t q = c - room.vertex_count();
    points.push_back(column_point(room, objects, c));
    normals.push_back(in_room ? room.normal(c) : objects.normals[q]);
    group.push_back(in_room ? 0 : static_cast<std::uint32_t>(objects.object_of_vertex(q) + 1));
  }
  t.proxies = build_receiver_proxies(
      points, normals, group,
      settings.proxy_spacing > 0
          ? settings.proxy_spacing
          : default_proxy_spacing(std::span<const Vec3>(points.data(), room.vertex_count())));
  t.proxied.resize(objects.object_count());
  for (std::size_t k = 0; k < objects.object_count(); ++k) {
    mark_proxied(room, objects, settings, t.proxies, k, 0, columns, t.proxied[k]);
    t.cones.push_back(trace_cones(room, objects, settings, k, t.proxied[k], nullptr, t.rays));
  }
  t.base = trace_rows(
      objects.vertex_count(), nullptr,
      [&](std::size_t q, RowScratch& scratch, Chunk& chunk) {
        trace_base_row(room, objects, settings, t.proxies, q, scratch, chunk);
      },
      t.rays);
  t.retraced_rows = (objects.object_count() + 1) * rows;
  return t;
}

void retrace_object_transfer(ObjectTransfer& t, const RuntimeScene& room,
                             const PlacedObjects& objects, const PlacedObjects& before,
                             const ObjectTransferSettings& settings,
                             std::span<const std::uint32_t> moved) {
  const std::size_t receivers = room.receivers(), rows = receivers + objects.vertex_count();
  const std::size_t columns = room.vertex_count() + objects.vertex_count();
  const ObjectIndexing indexing(room, objects);
  std::vector<bool> is_moved(objects.object_count(), false);
  std::vector<BoundingSphere> changed;  // where the moved objects were, and are now
  for (const std::uint32_t k : moved) {
    is_moved[k] = true;
    changed.push_back(before.bounds[k]);
    changed.push_back(objects.bounds[k]);
  }
  // Rows whose origin moved: the vertices of moved objects.
  std::vector<bool> origin_moved(rows, false);
  for (std::size_t q = 0; q < objects.vertex_count(); ++q) {
    origin_moved[receivers + q] = is_moved[objects.object_of_vertex(q)];
  }
  t.rays = 0;
  t.retraced_rows = 0;
  for (std::size_t k = 0; k < objects.object_count(); ++k) {
    // A moved object's cone rows all, from where it is now.
    if (is_moved[k]) {
      mark_proxied(room, objects, settings, t.proxies, k, 0, columns, t.proxied[k]);
      t.cones[k] = trace_cones(room, objects, settings, k, t.proxied[k], nullptr, t.rays);
      t.retraced_rows += rows;
      continue;
    }
    // Another's: whole where the origin moved; where its cone may meet a moved object, before
    // or now, the rays that do (which object a ray meets first may have changed).
    for (const std::uint32_t m : moved) {  // the moved objects' vertices, where they are now
      mark_proxied(room, objects, settings, t.proxies, k,
                   room.vertex_count() + objects.first_vertex[m],
                   room.vertex_count() + objects.first_vertex[m + 1], t.proxied[k]);
    }
    // Per row: 0 kept, 1 traced whole, 2 updated where its rays meet a moved sphere.
    std::vector<std::uint8_t> how(rows, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 1024), [&](const auto& range) {
      for (std::size_t row = range.begin(); row != range.end(); ++row) {
        const std::size_t column = indexing.column(row);
        if (origin_moved[row]) {
          how[row] = 1;
          continue;
        }
        if (!objects.visible(k) || (column < columns && t.proxied[k][column] != 0)) continue;
        const Origin o = origin_of(room, objects, row);
        bool overlap = false;
        for (std::size_t i = 0; i < changed.size() && !overlap; ++i) {
          overlap = cones_overlap(o.point, objects.bounds[k], changed[i]);
        }
        if (overlap && has_cone_row(room, objects, k, t.proxied[k], o, row)) how[row] = 2;
      }
    });
    std::vector<std::uint32_t> redo;
    std::vector<std::uint8_t> whole;  // per entry of redo
    for (std::size_t row = 0; row < rows; ++row) {
      if (how[row] == 0) continue;
      redo.push_back(static_cast<std::uint32_t>(row));
      whole.push_back(how[row] == 1 ? 1 : 0);
    }
    const ObjectRows& previous = t.cones[k];
    ObjectRows traced = trace_rows(
        0, &redo,
        [&](std::size_t i, RowScratch& scratch, Chunk& chunk) {
          const std::size_t row = redo[i];
          if (whole[i] != 0) {
            trace_cone_row(room, objects, settings, k, t.proxied[k], row, scratch, chunk);
          } else {
            update_cone_row(room, objects, before, settings, k, t.proxied[k], changed, previous,
                            row, scratch, chunk);
          }
        },
        t.rays, /*by_index=*/true);
    if (!redo.empty()) replace_rows(t.cones[k], redo, std::move(traced));
    t.retraced_rows += redo.size();
  }
  std::vector<std::uint32_t> redo;
  for (std::size_t q = 0; q < objects.vertex_count(); ++q) {
    if (origin_moved[receivers + q] && t.proxies.proxy_of[room.vertex_count() + q] >= 0) {
      redo.push_back(static_cast<std::uint32_t>(q));
    }
  }
  ObjectRows traced = trace_rows(
      0, &redo,
      [&](std::size_t q, RowScratch& scratch, Chunk& chunk) {
        trace_base_row(room, objects, settings, t.proxies, q, scratch, chunk);
      },
      t.rays);
  if (!redo.empty()) replace_rows(t.base, redo, std::move(traced));
  t.retraced_rows += redo.size();
}

}  // namespace relight
