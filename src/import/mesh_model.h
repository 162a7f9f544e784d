// glTF and OBJ models for `relight import`: each material of the file one element, see-through
// when the file says so (glTF KHR_materials_transmission or alphaMode BLEND, OBJ dissolve) or when
// its name matches a --window-material pattern. Such files name no storeys, spaces or site.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "import/building_model.h"

namespace relight {

// Reads `file` (.gltf, .glb, .obj) in relight's axes (glTF and OBJ are y up already).
// `window_materials`: case-insensitive patterns with `*` and `?` wildcards.
BuildingModel read_mesh_model(const std::filesystem::path& file,
                              const std::vector<std::string>& window_materials);

// Whether `name` matches `pattern` (`*` any run, `?` any one character), ignoring case.
bool matches_pattern(const std::string& name, const std::string& pattern);

}  // namespace relight
