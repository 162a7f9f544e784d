// glTF 2.0 import (.gltf with external or embedded buffers, .glb) through tinygltf.
#pragma once

#include <filesystem>

#include "scene/mesh_import.h"

namespace relight {

// Walks the default scene (scene 0 when none is named; every root node when the file has no
// scenes), applies node transforms (matrix or translation-rotation-scale), and takes the
// triangle primitives (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; indexed or not) with their
// float POSITION accessor. Albedo = baseColorFactor RGB; textures are ignored. Primitives
// without a material get the "default" one. Nodes with a mirroring transform keep their front
// faces (the glTF rule: a negative determinant flips the winding).
ImportedMesh import_gltf(const std::filesystem::path& file);

}  // namespace relight
