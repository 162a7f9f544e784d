// The movable objects' meshes: each object's triangles prepared as the room's are
// (welded, split to the scene's max_edge, crease-aware normals: scene/mesh_preparation.h), so
// that its vertices receive and reflect light the way the room's vertices do, and placed where a
// lighting state puts them (math/placement.h). Hidden objects keep their vertices (indices stay
// put from frame to frame) but have no triangles: they neither block, reflect nor show.
// Pinned by tests/sources/objects/object_mesh_test.cpp.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/runtime_scene.h"
#include "math/placement.h"
#include "math/vec3.h"
#include "scene/scene.h"
#include "trace/ray_tracer.h"

namespace relight {

// One object as the scene places it.
struct ObjectMesh {
  std::string name;
  Vec3 pivot;                            // centre of its bounding box
  std::vector<Vec3> positions, normals;  // per vertex; normals unit
  std::vector<Vec3> ray_points;          // where rays leave each vertex (receivers.h)
  std::vector<Triangle> triangles;
  std::vector<float> albedo;  // 3 per vertex: what it bounces (material/material_reflectance.h)
  // Per vertex, its material (index into the scene's); empty for files from before OMAT.
  std::vector<std::uint32_t> vertex_material;
  // 3 per vertex: its base colour texture's value (scene/surface_texture.h); empty: none.
  std::vector<float> texture;
};

// `object` is one of scene.objects (its materials are the scene's).
ObjectMesh prepare_object(const Scene& scene, const MovableObject& object);

// Every object as a state places it, vertices back to back in scene order.
struct PlacedObjects {
  std::vector<Vec3> positions, normals, ray_points;  // per vertex, placed
  std::vector<float> albedo;                         // 3 per vertex
  std::vector<std::uint32_t> first_vertex;     // per object, then the total: [first[i], first[i+1])
  std::vector<Triangle> triangles;             // the visible objects', indices into positions
  std::vector<std::uint32_t> triangle_object;  // per triangle: its object
  std::vector<BoundingSphere> bounds;          // per object; radius 0 when hidden
  std::vector<Bounds> boxes;                   // per object, its placed vertices'; 0 when hidden
  RayTracer tracer;                            // over `triangles` (ids: index into triangles)
  std::vector<RayTracer> own;                  // per object, over its triangles alone (same ids)

  // The object vertex q belongs to.
  std::size_t object_of_vertex(std::size_t q) const;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t object_count() const { return bounds.size(); }
  bool visible(std::size_t object) const { return bounds[object].radius > 0; }
};

// Whether placed object k passes through the room's surfaces: an edge of one of its triangles,
// shrunk 1 cm toward the object's centre (so that an object standing on the floor or against a
// wall does not count), crosses a triangle of `room`.
bool passes_through(const PlacedObjects& objects, std::size_t k, const RayTracer& room);

// The box around `points` (at least one).
Bounds box_around(std::span<const Vec3> points);
// A sphere around `points` (at least one): the centre of their bounding box, the radius to
// the farthest one.
BoundingSphere sphere_around(std::span<const Vec3> points);

// Whether a sphere comes within `margin` of the segment from a to b.
bool segment_near_sphere(Vec3 a, Vec3 b, const BoundingSphere& s, double margin);
// Whether a sphere comes within `margin` of the ray from a along unit d (a inside it counts).
bool ray_near_sphere(Vec3 a, Vec3 d, const BoundingSphere& s, double margin);

// Whether the ray from a along d meets the box `b` grown by `margin` on every side (a inside it
// counts): no ray that misses it can meet a triangle within it. Separating axes, no division:
// the box's three (a beyond a slab pointing away from it) and d × each of them (the line's
// distance from the centre across that axis beyond the box's reach). Inline: called once a
// direction where objects are traced leaf by leaf (sources/environment/environment_objects.h).
inline bool ray_meets_box(Vec3 a, Vec3 d, const Bounds& b, double margin) {
  const Vec3 w = (b.min + b.max) * 0.5 - a;
  const Vec3 e = (b.max - b.min) * 0.5 + Vec3{margin, margin, margin};
  const bool away = (std::abs(w.x) > e.x && w.x * d.x <= 0) ||
                    (std::abs(w.y) > e.y && w.y * d.y <= 0) ||
                    (std::abs(w.z) > e.z && w.z * d.z <= 0);
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  const bool beside = std::abs(w.y * d.z - w.z * d.y) > e.y * az + e.z * ay ||
                      std::abs(w.z * d.x - w.x * d.z) > e.x * az + e.z * ax ||
                      std::abs(w.x * d.y - w.y * d.x) > e.x * ay + e.y * ax;
  return !away && !beside;
}

// Throws std::invalid_argument when the placements are not one per object.
PlacedObjects place_objects(std::span<const ObjectMesh> objects,
                            std::span<const MovablePlacement> placements);

}  // namespace relight
