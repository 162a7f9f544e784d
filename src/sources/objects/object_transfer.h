// How movable objects change the light every receiver gathers, traced at run time whenever an
// object moves. The room's stored gather operator G (engine/gather_operator.h) holds where
// cosine-distributed rays from each receiver land in the empty room; an object placed in it changes
// only the rays that meet it, so only those are traced:
//
//  * room receivers (vertices and sensors): for each visible object, rays uniformly over the
//    cone of the object's bounding sphere (all of the hemisphere when the receiver is inside
//    it). A ray whose first object hit is this object and that meets it before any room
//    surface now sees the object instead of what the empty room showed there. With the
//    ray's weight w = Ω/N · cos θ / π, the correction row gets +w times the object
//    triangle's barycentrics (when its front side is seen) and −w times those of the room
//    triangle behind it (or, when the empty room showed a window there, −w times the light
//    through the glass). Counting a ray only for the first object it meets partitions the
//    directions among objects whose cones overlap, so none is counted twice.
//  * object vertices: a base row, cosine-distributed rays against the room, the glass and the
//    vertex's own object (traced when that object moves), and the same cone rows toward every
//    other object, "what the base row saw" being the room or its own object.
//
// With reflected light R = ρE per column, the irradiance gathered at a room receiver r is then
// (G·R)[r] + Σ_k (C_k·R)[r] and at an object vertex (B·R)[q] + Σ_k (C_k·R)[R + q] (H, the
// objects' rows) — the same estimator as the stored G
// (π times the mean luminance over cosine-distributed directions), restricted to the
// directions that changed. Columns are unified: room vertex v is column v, object vertex q
// column V + q.
//
// Iwasaki et al. 2007 instead make each object a secondary source from PCA basis radiance
// fields on concentric spheres (§3.1, §4.2–4.3) and shadow the room with occlusion fields; why
// relight traces instead, and the measurements, are in docs/decisions.md ("Movable objects"). Rows
// of vertices far from an object are not traced but interpolated from sparse proxy vertices
// (receiver_proxies.h), which stands in for the paper's fields where they are smooth. The paper's
// culling of small contributions (§5.4) is kept: a receiver spends rays on an object in proportion
// to the object's cosine-weighted share of its hemisphere, and none when that share is below
// `cull`. Pinned by tests/runtime/object_transfer_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/runtime_scene.h"
#include "sources/objects/object_mesh.h"
#include "sources/objects/receiver_proxies.h"

namespace relight {

struct ObjectTransferSettings {
  int object_rays = 128;  // cosine-distributed rays per object vertex
  // Rays a receiver spends on one object: its cosine-weighted share of the hemisphere times
  // cone_rays_per_hemisphere, clamped to [cone_rays_min, cone_rays_max].
  double cone_rays_per_hemisphere = 256;
  int cone_rays_min = 4;
  int cone_rays_max = 64;
  double cull = 1e-3;  // a share below this: no rays (the object changes < 0.1 % of the gather)
  int sensor_ray_factor = 8;  // sensors' rows take this many times the rays
  // Room vertices this many proxy spacings or more outside an object's sphere take their row
  // toward it from their proxies (receiver_proxies.h); spacing 0: default_proxy_spacing.
  double proxy_distance = 4;
  double proxy_spacing = 0;
};

// A ray that left through a window: its light is the portal's, looked up per frame.
struct GlassHit {
  std::uint32_t row = 0;
  std::uint32_t portal = 0;
  Vec3 direction;
  float weight = 0;  // signed: + seen now, − no longer seen
};

// Sparse rows in unified columns. Row i is entries [begin[i], end[i]) of `columns` and
// `values`; rows need not lie in order nor back to back: a drag appends the rows it retraces
// and points their rows there (replace_rows), leaving the old entries unused until there are
// as many unused entries as used ones, when the rows are packed again.
struct ObjectRows {
  std::vector<std::size_t> begin, end;
  std::vector<std::uint32_t> columns;
  std::vector<float> values;
  std::vector<GlassHit> glass;  // sorted by row
  std::size_t used = 0;         // entries that rows point at

  std::size_t rows() const { return begin.size(); }
  bool empty(std::size_t row) const { return begin[row] == end[row]; }
};

// The three numberings of the objects' term: transfer rows — the room's receivers (vertices,
// then sensors), then the object vertices (row R + q for vertex q); unified columns — room
// vertices, then object vertices (column V + q); and the bounce solver's rows — room vertices,
// object vertices, sensors (the columns first).
struct ObjectIndexing {
  std::size_t vertices = 0, receivers = 0, object_vertices = 0;  // V, R, Q
  static constexpr std::size_t kNone = ~std::size_t{0};

  ObjectIndexing(const RuntimeScene& room, const PlacedObjects& objects)
      : vertices(room.vertex_count()),
        receivers(room.receivers()),
        object_vertices(objects.vertex_count()) {}
  // The unified column of transfer row `row`'s vertex; kNone for a sensor.
  std::size_t column(std::size_t row) const {
    if (row < vertices) return row;
    return row < receivers ? kNone : vertices + (row - receivers);
  }
  // The transfer row of unified column c.
  std::size_t row(std::size_t c) const { return c < vertices ? c : receivers + (c - vertices); }
  // The solver row of transfer row `row`.
  std::size_t solver_row(std::size_t row) const {
    if (row < vertices) return row;
    return row < receivers ? row + object_vertices : vertices + (row - receivers);
  }
};

// Rows are numbered over every receiver that gathers: the room's receivers (vertices, then
// sensors), then the object vertices (PlacedObjects order): row R + q for vertex q.
struct ObjectTransfer {
  // Per object k, one row per receiver: what k changes in what that receiver gathers (C_k;
  // empty rows for k's own vertices, which see their object in their base row).
  std::vector<ObjectRows> cones;
  // One row per object vertex: its gather of the room and of its own object (traced when the
  // object moves; empty but at proxies, the others take their proxies' rows); the other
  // objects come in through `cones`.
  ObjectRows base;
  // Of the room's and the objects' vertices, in unified columns (room vertex v, object vertex
  // q: V + q).
  ReceiverProxies proxies;
  // Per object, per unified column: 1 when that vertex's row toward the object is left empty
  // and taken from its proxies' rows instead (takes_proxy_row, as placed now).
  std::vector<std::vector<std::uint8_t>> proxied;
  std::uint64_t rays = 0;         // traced by the last update (trace or retrace; 0: none)
  std::size_t retraced_rows = 0;  // rows (of cones and base) traced by it
};

// Of a receiver at `origin` (already off its surface) with unit normal `normal`: the share of
// its cosine-weighted hemisphere a sphere may cover, Ω/π · clamp(n · axis + sin α, 0, 1) (an
// upper bound), 1 inside the sphere, 0 for a sphere of radius 0 (a hidden object).
double sphere_share(Vec3 origin, Vec3 normal, const BoundingSphere& sphere);

ObjectTransfer trace_object_transfer(const RuntimeScene& room, const PlacedObjects& objects,
                                     const ObjectTransferSettings& settings);

// After objects `moved` moved (or were hidden or shown) from where `before` placed them:
// retraces what a move can change — every cone row of a moved object, every row whose origin
// moved (the moved objects' vertices: their cone rows, and the base rows at proxies), and in
// the rows of another object's cone the rays that meet a moved object's sphere, before or now
// (which object a ray meets first may have changed: each such ray is traced among the objects
// before, its contribution taken off, and as placed now) — and keeps the rest. A drag traces
// about one object's share of the rays, not all of them.
void retrace_object_transfer(ObjectTransfer& transfer, const RuntimeScene& room,
                             const PlacedObjects& objects, const PlacedObjects& before,
                             const ObjectTransferSettings& settings,
                             std::span<const std::uint32_t> moved);

}  // namespace relight
