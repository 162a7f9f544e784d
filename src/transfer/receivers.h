// Receivers of precomputed transfer (ARCHITECTURE §4.1): every prepared-mesh vertex,
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

Receivers make_receivers(const Scene& scene, const PreparedMesh& mesh);

}  // namespace relight
