#include "import/mesh_model.h"

#include <cctype>
#include <map>

#include "scene/mesh_import.h"

namespace relight {

bool matches_pattern(const std::string& name, const std::string& pattern) {
  // Iterative wildcard match: on a mismatch after a '*', the star takes one more character.
  std::size_t n = 0, p = 0, star = std::string::npos, resume = 0;
  const auto same = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  };
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || same(pattern[p], name[n]))) {
      ++n;
      ++p;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

BuildingModel read_mesh_model(const std::filesystem::path& file,
                              const std::vector<std::string>& window_materials) {
  const ImportedMesh mesh = import_mesh(file);
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  BuildingModel model;
  model.format = extension == ".obj" ? "OBJ" : "glTF";
  model.elements.resize(mesh.materials.size());
  // Each material's part keeps only the vertices its triangles use.
  std::vector<std::map<std::uint32_t, std::uint32_t>> vertex_of(mesh.materials.size());
  for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
    const ImportedMaterial& material = mesh.materials[m];
    ModelElement& element = model.elements[m];
    element.id = static_cast<std::uint32_t>(m);
    element.name = material.name;
    ModelPart part;
    part.material_name = material.name;
    if (material.name != kDefaultImportMaterialName) part.albedo = material.albedo;
    part.transparent = material.transparent;
    for (const std::string& pattern : window_materials)
      if (matches_pattern(material.name, pattern)) part.transparent = true;
    element.parts.push_back(std::move(part));
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t m = mesh.triangle_material[t];
    ModelPart& part = model.elements[m].parts.front();
    Triangle local{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      const auto [it, added] =
          vertex_of[m].try_emplace(v, static_cast<std::uint32_t>(part.positions.size()));
      if (added) part.positions.push_back(mesh.positions[v]);
      local[k] = it->second;
    }
    part.triangles.push_back(local);
  }
  std::erase_if(model.elements,
                [](const ModelElement& e) { return e.parts.front().triangles.empty(); });
  return model;
}

}  // namespace relight
