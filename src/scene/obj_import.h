// Wavefront OBJ (+ MTL) import through tinyobjloader, guarded by a validating pass that
// gives broken files a "FILE:LINE: reason" error instead of tinyobjloader's silent repair.
#pragma once

#include <filesystem>

#include "scene/mesh_import.h"

namespace relight {

// Polygons are triangulated with their winding kept; materials come from the .mtl files
// named by `mtllib` (albedo = Kd as written, taken as linear RGB). Faces without a known
// material get the "default" one; a missing .mtl is not an error.
ImportedMesh import_obj(const std::filesystem::path& file);

}  // namespace relight
