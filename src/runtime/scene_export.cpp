#include "runtime/scene_export.h"

#include <string>

namespace relight {

namespace fs = std::filesystem;

namespace {

nlohmann::json vec(Vec3 v) {
  return {v.x, v.y, v.z};
}

// Every relative path under a "file" key, made absolute against `folder`.
void absolute_files(nlohmann::json& node, const fs::path& folder) {
  if (node.is_array()) {
    for (nlohmann::json& element : node) absolute_files(element, folder);
    return;
  }
  if (!node.is_object()) return;
  for (auto& [key, value] : node.items()) {
    if (key == "file" && value.is_string()) {
      const fs::path p = value.get<std::string>();
      if (p.is_relative()) value = (folder / p).lexically_normal().string();
    } else {
      absolute_files(value, folder);
    }
  }
}

}  // namespace

nlohmann::json distribution_json(const DistributionSpec& d) {
  switch (d.type) {
    case DistributionType::kIsotropic:
      return {{"type", "isotropic"}, {"candela", d.candela}};
    case DistributionType::kCosinePower:
      return {{"type", "cosine_power"},
              {"candela", d.candela},
              {"exponent", d.exponent},
              {"cutoff_deg", d.cutoff_deg}};
    case DistributionType::kCurve:
      return {{"type", "curve"}, {"gamma_deg", d.gamma_deg}, {"candela", d.curve_candela}};
    case DistributionType::kIes:
    case DistributionType::kLdt:
      return {{"type", d.type == DistributionType::kIes ? "ies" : "ldt"},
              {"file", fs::absolute(d.file).lexically_normal().string()}};
  }
  return nullptr;
}

nlohmann::json scene_json_with_layout(const nlohmann::json& scene_json, const fs::path& scene_file,
                                      const LightingState& state) {
  nlohmann::json out = scene_json;
  const fs::path folder = fs::absolute(scene_file).parent_path();
  absolute_files(out, folder);
  nlohmann::json luminaires = nlohmann::json::array();
  for (const LuminaireState& l : state.luminaires) {
    if (!l.on) continue;
    nlohmann::json j = {{"name", l.name},
                        {"position", vec(l.position)},
                        {"aim", vec(l.aim)},
                        {"c0", vec(l.c0)},
                        {"color", {l.color.r, l.color.g, l.color.b}},
                        {"dimmer", l.dimmer},
                        {"distribution", distribution_json(l.distribution)}};
    if (l.has_size) j["size"] = vec(l.size);
    luminaires.push_back(std::move(j));
  }
  out["luminaires"] = std::move(luminaires);
  return out;
}

}  // namespace relight
