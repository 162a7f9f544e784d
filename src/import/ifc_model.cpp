#include "import/ifc_model.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/child_process.h"
#include "common/input_error.h"
#include "common/installed_files.h"
#include "common/read_file.h"
#include "math/srgb.h"

namespace relight {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kStepHeader = "ISO-10303-21;";
constexpr std::string_view kStepTrailer = "END-ISO-10303-21;";

// A folder of its own under the system's temporary folder, removed with this object.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "relight-import-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) fail_input(pattern, "cannot create a temporary folder");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The STEP physical file's frame (ISO 10303-21): it opens with its header keyword and closes with
// its trailer, so a file cut short lacks the trailer.
void check_step_frame(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_input(file.string(), "cannot open it");
  std::string head(256, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t start = head.find_first_not_of("\xEF\xBB\xBF \t\r\n");
  if (start == std::string::npos || head.compare(start, kStepHeader.size(), kStepHeader) != 0)
    fail_input(file.string(), "not an IFC file: it does not begin with ISO-10303-21;");
  in.clear();
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::streamoff>(in.tellg());
  const std::streamoff tail_size = std::min<std::streamoff>(size, 1024);
  in.seekg(size - tail_size);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.read(tail.data(), tail_size);
  if (tail.find(kStepTrailer) == std::string::npos)
    fail_input(file.string(), "truncated: the IFC file does not end with END-ISO-10303-21;");
}

// Runs `node ifc-extract.mjs MODEL OUT` and waits: its exit code and the end of its stderr.
ChildResult run_extractor(const fs::path& model, const fs::path& out) {
  const fs::path script = importer_folder() / "ifc-extract.mjs";
  if (!fs::is_regular_file(script))
    fail_input(model.string(), "the IFC reader " + script.string() + " is missing");
  try {
    return run_child({"node", script.string(), model.string(), out.string()});
  } catch (const std::runtime_error&) {
    fail_input(
        model.string(),
        "reading IFC needs node (Debian package nodejs) and web-ifc: run scripts/bootstrap.sh");
  }
}

std::string text_of(const nlohmann::json& value) {
  return value.is_string() ? value.get<std::string>() : std::string();
}

double number_of(const nlohmann::json& value, double otherwise) {
  return value.is_number() ? value.get<double>() : otherwise;
}

Vec3 ifc_vector(const nlohmann::json& m, int first) {
  return {m.at(first).get<double>(), m.at(first + 1).get<double>(), m.at(first + 2).get<double>()};
}

ModelPart read_part(const nlohmann::json& j, const fs::path& file) {
  ModelPart part;
  const nlohmann::json& colour = j.at("color");
  if (colour.is_array() && colour.size() == 4) {
    part.albedo = Rgb{srgb_decode(colour[0].get<double>()), srgb_decode(colour[1].get<double>()),
                      srgb_decode(colour[2].get<double>())};
    part.transparent = colour[3].get<double>() < 1;
  }
  part.material_name = text_of(j.value("material_name", nlohmann::json()));
  const auto& p = j.at("positions").get_ref<const nlohmann::json::array_t&>();
  if (p.size() % 3 != 0) fail_input(file.string(), "the IFC reader wrote a broken vertex array");
  part.positions.reserve(p.size() / 3);
  for (std::size_t i = 0; i < p.size(); i += 3)
    part.positions.push_back(
        from_ifc_axes({p[i].get<double>(), p[i + 1].get<double>(), p[i + 2].get<double>()}));
  const auto& ix = j.at("indices").get_ref<const nlohmann::json::array_t&>();
  if (ix.size() % 3 != 0) fail_input(file.string(), "the IFC reader wrote a broken index array");
  for (std::size_t i = 0; i < ix.size(); i += 3) {
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      const auto index = ix[i + static_cast<std::size_t>(k)].get<std::uint64_t>();
      if (index >= part.positions.size())
        fail_input(file.string(), "the IFC reader wrote an index out of range");
      t[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(index);
    }
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) part.triangles.push_back(t);
  }
  return part;
}

BuildingModel parse_extract(const nlohmann::json& doc, const fs::path& file) {
  BuildingModel model;
  model.format = text_of(doc.value("schema", nlohmann::json()));
  if (model.format.empty()) model.format = "IFC";
  std::map<std::uint32_t, int> storey_index;
  for (const nlohmann::json& s : doc.at("storeys")) {
    ModelStorey storey;
    storey.id = s.at("id").get<std::uint32_t>();
    storey.name = text_of(s.value("name", nlohmann::json()));
    if (storey.name.empty()) storey.name = text_of(s.value("long_name", nlohmann::json()));
    if (storey.name.empty()) storey.name = "storey #" + std::to_string(storey.id);
    storey.elevation = number_of(s.value("elevation", nlohmann::json()), 0);
    model.storeys.push_back(storey);
  }
  std::stable_sort(
      model.storeys.begin(), model.storeys.end(),
      [](const ModelStorey& a, const ModelStorey& b) { return a.elevation < b.elevation; });
  for (std::size_t i = 0; i < model.storeys.size(); ++i)
    storey_index[model.storeys[i].id] = static_cast<int>(i);

  const nlohmann::json& site = doc.value("site", nlohmann::json());
  if (site.is_object() && site.value("latitude", nlohmann::json()).is_number() &&
      site.value("longitude", nlohmann::json()).is_number()) {
    ModelSite s;
    s.latitude = site.at("latitude").get<double>();
    s.longitude = site.at("longitude").get<double>();
    s.elevation_m = number_of(site.value("elevation_m", nlohmann::json()), 0);
    const double north = number_of(site.value("true_north_deg", nlohmann::json()), 0);
    s.north_deg = std::fmod(std::fmod(north, 360.0) + 360.0, 360.0);
    model.site = s;
  }

  for (const nlohmann::json& e : doc.at("elements")) {
    ModelElement element;
    element.id = e.at("id").get<std::uint32_t>();
    element.ifc_class = text_of(e.at("class"));
    element.name = text_of(e.value("name", nlohmann::json()));
    element.long_name = text_of(e.value("long_name", nlohmann::json()));
    element.type_name = text_of(e.value("type_name", nlohmann::json()));
    element.predefined_type = text_of(e.value("predefined_type", nlohmann::json()));
    element.light_fixture = e.value("is_light_fixture", false);
    element.photometry = text_of(e.value("photometry", nlohmann::json()));
    const nlohmann::json& parent = e.value("parent", nlohmann::json());
    if (parent.is_number_unsigned()) element.parent = parent.get<std::uint32_t>();
    const nlohmann::json& storey = e.value("storey", nlohmann::json());
    if (storey.is_number_unsigned()) {
      const auto found = storey_index.find(storey.get<std::uint32_t>());
      if (found != storey_index.end()) element.storey = found->second;
    }
    const nlohmann::json& placement = e.value("placement", nlohmann::json());
    if (placement.is_array() && placement.size() == 16) {
      element.x_axis = normalize(from_ifc_axes(ifc_vector(placement, 0)));
      element.z_axis = normalize(from_ifc_axes(ifc_vector(placement, 8)));
      element.origin = from_ifc_axes(ifc_vector(placement, 12));
    }
    for (const nlohmann::json& p : e.at("parts")) element.parts.push_back(read_part(p, file));
    model.elements.push_back(std::move(element));
  }
  return model;
}

}  // namespace

fs::path importer_folder() {
  fs::path installed = installed_share_folder("importer");
  std::error_code ec;
  if (!installed.empty() && fs::is_regular_file(installed / "ifc-extract.mjs", ec))
    return installed;
  return fs::path(RELIGHT_IMPORTER_DIR);
}

BuildingModel read_ifc_model(const fs::path& file) {
  check_step_frame(file);
  const ScratchFolder scratch;
  const fs::path out = scratch.path() / "model.json";
  const ChildResult reader = run_extractor(file, out);
  if (reader.status != 0) {
    const std::string why = last_line(reader.err_end);
    if (why.find("web-ifc is not installed") != std::string::npos)
      fail_input(file.string(), "reading IFC needs web-ifc: run scripts/bootstrap.sh");
    fail_input(file.string(),
               "web-ifc cannot read it as IFC" + (why.empty() ? "" : " (" + why + ")"));
  }
  return parse_ifc_extract(read_file(out), file);
}

BuildingModel parse_ifc_extract(const std::string& json, const fs::path& file) {
  try {
    return parse_extract(nlohmann::json::parse(json), file);
  } catch (const nlohmann::json::exception& e) {
    fail_input(file.string(), std::string("the IFC reader's output is broken: ") + e.what());
  }
}

}  // namespace relight
