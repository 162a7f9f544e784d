// What the run time reads of the near-field emitters' stored transfer (docs/rlt-format.md,
// NFTR and the gather operator NGRO/NGCO/NGVA) and the receivers and static occluders their
// lighting needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "scene/triangle_soup.h"

namespace relight {

struct NearfieldTransferView {
  int sh_order = 0;                 // 0: the scene has no emitters
  std::span<const float> transfer;  // receivers × K shadowed transfer, K = sh_order²
  // The gather operator in compressed rows (receivers × vertices), empty without
  // "nearfield_interreflection": row r's entries are [rows[r], rows[r + 1]).
  std::span<const std::uint32_t> gather_rows, gather_columns;
  std::span<const float> gather_values;
  std::vector<float> vertex_albedo;      // 3 per vertex
  std::vector<Vec3> receiver_positions;  // vertices, then sensors
  std::vector<Vec3> receiver_normals;    // vertices, then sensors; unit
  std::size_t vertex_count = 0;
  std::span<const Vec3> mesh_positions;  // the static scene, for shadows at sensors and pixels
  std::vector<Triangle> opaque_triangles;
};

}  // namespace relight
