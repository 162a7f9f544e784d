// What the run time traces and bounces its own light through: light that no stored response can
// hold — the exact sun through a window, near-field emitters a hand's width from a surface — is
// computed at run time at every receiver, and its interreflection bounced through the precompute's
// own gather operator (engine/gather_operator.h) with the precompute's own solver
// (engine/bounce_solver.h). This is the one owner of that machinery: the receivers, the static
// opaque mesh and its ray tracer, the portals' glass, the vertices' albedo and the stored gather
// operator, and the quadrature of each vertex's hat function that turns an exact irradiance field
// into what a vertex reflects.
//
// What bounces at a vertex is the mean of the exact irradiance over its hat function φ_v,
//     Ē_v = ∫ E φ_v dA / ∫ φ_v dA,
// so that the light interpolated between vertices carries the flux the surfaces receive: the
// value at the vertex alone misses a sun patch's edge between vertices and underestimates a
// peaked pool of light (an emitter's ceiling 2.5 % too dark at 0.25 m edges,
// tests/cli/emitter_probe_test.cpp). The quadrature splits each triangle into s² equal
// sub-triangles and takes E once at each one's centroid, weighted by the centroid's
// barycentric coordinate toward each of the triangle's three vertices — for sharp fields,
// the sun's patch; or (s = 0) takes E once per corner at the corner's φ-weighted centroid,
// barycentric (½, ¼, ¼), weight A/3 — exact for E linear on the triangle, for smooth fields
// (an emitter's pool of light). Pinned by tests/engine/runtime_scene_test.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/bounce_solver.h"
#include "engine/gather_operator.h"
#include "engine/receivers.h"
#include "engine/sensor_importance.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

inline constexpr std::uint32_t kNoMaterial = 0xffffffffu;

// The stored scene as the run time reads it (sources/transfer_file.h fills it from a .rlt or
// from a precompute in memory).
struct RuntimeSceneView {
  std::size_t vertex_count = 0;
  std::vector<Vec3> receiver_positions;  // vertices, then sensors
  std::vector<Vec3> receiver_normals;    // vertices, then sensors; unit
  std::span<const Vec3> mesh_positions;  // the vertices
  std::vector<Triangle> opaque_triangles;
  std::vector<std::uint32_t> opaque_ids;    // per opaque triangle: its index in the mesh
  std::vector<Triangle> glass_triangles;    // the portals' glass
  std::vector<std::uint32_t> glass_portal;  // per glass triangle: its portal (scene order)
  std::vector<float> vertex_albedo;         // 3 per vertex
  // Per vertex its material (scene order), for live material edits; empty when the file
  // predates MMAT; kNoMaterial for a vertex no triangle uses.
  std::vector<std::uint32_t> vertex_material;
  // 3 per vertex: its base colour texture's value (scene/surface_texture.h), which multiplies
  // an edited material's base colour; empty when no vertex has a texture.
  std::vector<float> vertex_texture;
  // The gather operator in compressed rows (receivers × vertices), empty when the precompute
  // did not keep it: row r's entries are [rows[r], rows[r + 1]).
  std::span<const std::uint32_t> gather_rows, gather_columns;
  std::span<const float> gather_values;
};

// A sphere that holds a set of triangles.
struct BoundingSphere {
  Vec3 centre;
  double radius = 0;
};

// What holds a portal's glass: a sphere, and a plane slab with a rectangle in it — the plane
// through the sphere's centre with the normal of the glass's largest triangle, the extent of
// the glass vertices along two axes of that plane and their largest distance from it
// (`depth`; 0 for flat glass). Rays of the sun that cannot cross the rectangle grown by the
// slab cannot pass the glass (sources/portals/portal_sun.cpp culls the room's triangles so).
struct GlassBounds {
  BoundingSphere sphere;
  Vec3 normal{0, 1, 0}, u{1, 0, 0}, v{0, 0, 1};       // unit; u, v in the plane
  double u_min = 0, u_max = 0, v_min = 0, v_max = 0;  // from sphere.centre along u, v
  double depth = 0;
};

// Irradiance (lx, RGB) at a point with a unit normal; called from many threads at once.
using IrradianceField = std::function<Rgb(Vec3 point, Vec3 normal)>;
// Whether a field may light any point of the triangle (a, b, c) of unit normal n: false lets
// hat_means skip the triangle's quadrature points (a sun that reaches only a patch of a
// million-triangle scene). Called from many threads at once.
using TriangleFilter = std::function<bool(Vec3 a, Vec3 b, Vec3 c, Vec3 normal)>;

class RuntimeScene {
 public:
  // Throws std::invalid_argument when the view's sizes disagree.
  RuntimeScene(const RuntimeSceneView& view, BounceSettings bounce);

  std::size_t receivers() const { return ray_points_.size(); }
  const std::vector<Vec3>& receiver_positions() const { return receivers_.positions; }
  std::size_t vertex_count() const { return vertex_count_; }
  // Where rays from receiver r start (engine/receivers.h receiver_ray_points) and its normal.
  Vec3 ray_point(std::size_t r) const { return ray_points_[r]; }
  const std::vector<Vec3>& ray_points() const { return ray_points_; }
  Vec3 normal(std::size_t r) const { return receivers_.normals[r]; }
  // The static opaque scene (ids: the triangle's index in the mesh) and the portals' glass
  // (ids: the portal's index).
  const RayTracer& occluders() const { return occluders_; }
  const RayTracer& glass() const { return glass_; }
  // What holds portal p's glass (a sphere of radius 0 for a portal with none): the sphere
  // about the centre of its vertices' bounding box, to the farthest one; the slab around it.
  GlassBounds glass_bounds(std::uint32_t portal) const {
    return portal < glass_bounds_.size() ? glass_bounds_[portal] : GlassBounds{};
  }

  // Whether the precompute kept the gather operator (bounce() is then available).
  bool can_bounce() const { return gather_.has_value(); }
  // The stored gather operator (needs can_bounce()) and the receivers it gathers for.
  const GatherOperator& gather() const { return gather_.value(); }
  const Receivers& receiver_set() const { return receivers_; }
  // The opaque triangle an occluders() hit reports (by its id, the mesh index) and the
  // mesh's vertex positions.
  const Triangle& opaque_triangle(std::uint32_t id) const { return triangles_[opaque_slot_[id]]; }
  // Every opaque triangle and, in the same order, its id.
  const std::vector<Triangle>& opaque_triangles() const { return triangles_; }
  const std::vector<std::uint32_t>& opaque_ids() const { return opaque_ids_; }
  const std::vector<Vec3>& mesh_positions() const { return positions_; }

  // out (3 per receiver): at vertices the mean of `irradiance` over the hat function with s²
  // points per adjacent triangle (s = subdivision ≥ 1), or with the corners' φ-weighted
  // centroids (s = 0); a vertex with no triangle: the value at its ray point; at sensors 0
  // (they reflect nothing, and bounce() reads only vertex rows).
  // With `may_light`, triangles it rejects contribute nothing. With `min_edge` > 0 (m) a
  // triangle is split no finer than sub-triangles of that longest edge (a 4 cm triangle of a
  // scanned model needs one point, a 30 cm one of a wall all s²).
  void hat_means(const IrradianceField& irradiance, int subdivision, std::span<float> out,
                 const TriangleFilter& may_light = {}, double min_edge = 0) const;

  // The interreflected light (3 per receiver) of the direct irradiance `direct` (3 per
  // receiver; its vertex rows are what the surfaces reflect): channel c bounces with the
  // albedo's channel c (engine/bounce_solver.h solve_bounces_rgb). With `warm`, `indirect`
  // holds the solution for the previous, similar light and the iteration starts from it.
  // Returns the wall time, seconds. Needs can_bounce().
  double bounce(std::span<const float> direct, std::span<float> indirect, bool warm) const;

  // Solves every sensor's importance (engine/sensor_importance.h) once, for
  // bounce_to_sensors: seconds on a room (the demo room's 414 sensors). Needs can_bounce().
  // With `solved` (the same transfer's, solved by another RuntimeScene of it), takes that
  // instead; throws std::invalid_argument when its vertex and sensor counts are not these.
  void solve_sensor_importance(std::shared_ptr<const SensorImportance> solved = nullptr);
  bool has_sensor_importance() const { return importance_ != nullptr; }
  std::shared_ptr<const SensorImportance> sensor_importance() const { return importance_; }
  // Wall time of its solve, seconds (0 before it).
  double sensor_importance_seconds() const { return importance_ ? importance_->seconds : 0; }
  // bounce() at the sensor rows alone, through their importance: the vertex rows of
  // `indirect` are set to 0. Needs solve_sensor_importance(). Returns the wall time, seconds.
  double bounce_to_sensors(std::span<const float> direct, std::span<float> indirect) const;

 private:
  std::size_t vertex_count_ = 0;
  std::vector<Vec3> ray_points_;  // per receiver
  std::vector<Vec3> positions_;
  std::vector<Triangle> triangles_;         // opaque
  std::vector<std::uint32_t> opaque_ids_;   // per opaque triangle: its mesh index
  std::vector<std::uint32_t> opaque_slot_;  // mesh triangle index → index into triangles_
  RayTracer occluders_, glass_;
  std::vector<GlassBounds> glass_bounds_;  // per portal
  std::optional<GatherOperator> gather_;
  std::shared_ptr<const SensorImportance> importance_;  // read-only: shared with twins
  Receivers receivers_;  // positions, normals, albedo per receiver (0 at sensors)
  BounceSettings bounce_;
  // Vertex → the (triangle, corner) pairs around it, compressed: [first[v], first[v + 1]).
  std::vector<std::size_t> corner_first_;
  std::vector<std::uint32_t> corners_;  // 3 · triangle + corner
  std::vector<double> hat_area_;        // ∫ φ_v dA per vertex
};

}  // namespace relight
