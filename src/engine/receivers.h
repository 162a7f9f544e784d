// Receivers of precomputed transfer: every prepared-mesh vertex,
// then every sensor point, each with a position, a unit normal and an albedo (sensors
// measure and never reflect: albedo 0). Transfer stores irradiance E per receiver; a
// vertex's outgoing luminance is albedo/π · E.
#pragma once

#include <cstddef>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"

namespace relight {

struct Receivers {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
  std::vector<Rgb> albedo;
  std::size_t vertex_count = 0;  // receivers [0, vertex_count) are mesh vertices
  std::size_t sensor_count = 0;  // then the sensors, in scene order

  std::size_t size() const { return positions.size(); }
};

// The one place that knows the receiver order: receiver index of sensor s (scene order),
// after the vertex_count mesh vertices.
constexpr std::size_t sensor_receiver(std::size_t vertex_count, std::size_t s) {
  return vertex_count + s;
}

Receivers make_receivers(const Scene& scene, const PreparedMesh& mesh);

// Where rays leaving each receiver start, before the push along the normal: a vertex on a
// crease (the foot of a wall, a room corner, a ceiling edge) also lies in the plane of its
// neighbouring faces, and rays from it that run in or toward those planes start on them
// — gather rays slip out of the room, and shadow rays to a luminaire mounted in the
// ceiling plane graze the ceiling and are falsely blocked. Vertices are therefore moved a
// little toward the middle of their own triangles (toward the centroid of their one-ring,
// within the tangent plane): by 1e-4 · max(|p|∞, 1) m, at most a quarter of the way to the
// centroid, far below any lighting gradient. Sensors are used as given.
std::vector<Vec3> receiver_ray_points(const Receivers& receivers, const PreparedMesh& mesh);

}  // namespace relight
