// Picks the reader for a mesh file by its extension.
#include "scene/mesh_import.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "common/input_error.h"
#include "scene/gltf_import.h"
#include "scene/obj_import.h"
#include "scene/ply_import.h"

namespace relight {

ImportedMesh import_mesh(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return import_obj(file);
  if (extension == ".gltf" || extension == ".glb") return import_gltf(file);
  if (extension == ".ply") return import_ply(file);
  fail_input(file.string(),
             "unsupported mesh format '" + extension + "' (expected .obj, .gltf, .glb or .ply)");
}

}  // namespace relight
