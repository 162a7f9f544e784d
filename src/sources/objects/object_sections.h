// The movable objects' sections of a transfer file (docs/rlt-format.md, "Movable objects"):
// each object's prepared mesh as the precompute made it (sources/objects/object_mesh.h), so that
// the run time places exactly the vertices the precompute reported and needs neither the
// object's mesh files nor a second mesh preparation. Everything else an object needs is traced
// at run time (object_transfer.h). Written and read here; store/ holds the container.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "sources/objects/object_mesh.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// The arrays written, kept alive until the writer writes.
struct ObjectSectionData {
  std::vector<std::uint32_t> counts;  // per object: vertices, triangles
  std::vector<float> positions, normals, ray_points, pivots, albedo;
  std::vector<std::uint32_t> triangles;  // per object, indices local to it
  std::vector<std::uint32_t> materials;  // per vertex, into the scene's materials
  std::vector<float> texture;            // 3 per vertex when some object has a texture
};

// Adds the sections of `objects` (none for a scene without objects) to `writer`, which keeps
// spans into `data`.
void write_object_sections(RltWriter& writer, std::span<const ObjectMesh> objects,
                           ObjectSectionData& data);

// The objects of `scene` (their names) from `file`; InputError naming `where` when the sections
// are missing or disagree with the scene.
std::vector<ObjectMesh> read_object_sections(const RltFile& file, const Scene& scene,
                                             const std::string& where);

// Bytes one object's mesh takes in the file.
std::size_t object_section_bytes(const ObjectMesh& object);

}  // namespace relight
