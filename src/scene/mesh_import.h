// Mesh files (OBJ, glTF 2.0, PLY) read into one plain form: positions, triangles with the
// file's winding, and one material per triangle. The scene loader places these in the world and
// mesh preparation (mesh_preparation.h) turns them into receivers. Every reader reports bad input
// as InputError "FILE[:LINE]: reason", never crashes on it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle_soup.h"

namespace relight {

struct ImportedMaterial {
  std::string name;
  Rgb albedo;  // linear Rec.709 diffuse reflectance (glTF base colour)
  // glTF metallicFactor / roughnessFactor, when the file gives either (scene/scene.h Material).
  bool glossy = false;
  double metallic = 0, roughness = 1;
  // See-through in the file: glTF KHR_materials_transmission (a transmissionFactor above 0) or
  // alphaMode BLEND, an OBJ material's dissolve `d` below 1 (or `Tr` above 0). The scene loader
  // ignores it; `relight import` makes such glass window portals.
  bool transparent = false;
};

struct ImportedMesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;               // counter-clockwise seen from the front
  std::vector<std::uint32_t> triangle_material;  // one per triangle, into `materials`
  std::vector<ImportedMaterial> materials;       // only those some triangle uses
  TriangleTextures textures;  // glTF base colour textures; empty for OBJ, PLY and untextured
};

// Albedo of the material given to triangles whose file names none.
inline constexpr Rgb kDefaultImportAlbedo{0.8, 0.8, 0.8};
inline constexpr const char* kDefaultImportMaterialName = "default";

// Reads .obj, .gltf, .glb or .ply (extension compared case-insensitively); any other
// extension, an unreadable file or a broken one throws InputError.
ImportedMesh import_mesh(const std::filesystem::path& file);

}  // namespace relight
