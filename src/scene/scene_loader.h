// Reads a scene JSON file (docs/scene-format.md) into a Scene, validating every value
// and reporting "FILE:/json/pointer: reason" on bad input. Relative file paths resolve
// against the scene file's folder.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "scene/json_node.h"
#include "scene/scene.h"

namespace relight {

// Photometry files carried along (by a .rlt file), keyed by resolved path: used instead
// of reading the disk.
using EmbeddedFiles = std::map<std::string, std::shared_ptr<const std::string>>;

Scene load_scene(const std::filesystem::path& file);
// The same from an already parsed document; `file` names it in messages and gives the
// folder for relative paths. `materials`, when given, are the scene's materials in order as
// a precompute loaded them, used instead of the document's: a .rlt keeps them because it
// does not keep the geometry, whose mesh files added theirs ("FILE/NAME"), and the stored
// triangles refer to them by index.
Scene scene_from_json(const nlohmann::json& document, const std::filesystem::path& file,
                      const EmbeddedFiles* embedded = nullptr,
                      const std::vector<Material>* materials = nullptr);

// Parses a distribution object D (shared with run-time lighting states).
DistributionSpec parse_distribution(const JsonNode& node, const std::filesystem::path& base_dir,
                                    const EmbeddedFiles* embedded = nullptr);

// A material's reflectance keys (shared with run-time lighting states' material edits):
// `albedo` when given, `metallic` and `roughness` (0..1; either makes the material glossy).
void read_reflectance(const JsonNode& node, Material& material);

}  // namespace relight
