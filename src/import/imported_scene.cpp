#include "import/imported_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "common/read_file.h"
#include "import/floor_grid.h"
#include "scene/triangle_soup.h"
#include "trace/ray_tracer.h"
#include "trace/surface_orientation.h"

namespace relight {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

// The CIE traditional overcast sky of 10 klx on the horizontal: lux at a point are its daylight
// factor in per cent times 100.
constexpr double kSkyIlluminance = 10000;

bool starts_with(const std::string& s, std::string_view prefix) {
  return s.rfind(prefix, 0) == 0;
}

bool is_space(const ModelElement& e) {
  return e.ifc_class == "IFCSPACE";
}
bool is_window(const ModelElement& e) {
  return e.ifc_class == "IFCWINDOW";
}
bool is_door(const ModelElement& e) {
  return e.ifc_class == "IFCDOOR";
}
bool is_furniture(const ModelElement& e) {
  return e.ifc_class == "IFCFURNISHINGELEMENT" || e.ifc_class == "IFCFURNITURE" ||
         e.ifc_class == "IFCSYSTEMFURNITUREELEMENT";
}
bool is_slab(const ModelElement& e) {
  return starts_with(e.ifc_class, "IFCSLAB");
}
// Products that are not surfaces of the building.
bool is_not_surface(const ModelElement& e) {
  return e.ifc_class == "IFCOPENINGELEMENT" || e.ifc_class == "IFCSITE" ||
         e.ifc_class == "IFCANNOTATION" || e.ifc_class == "IFCGRID" || is_space(e);
}

// Where a face of an element without a colour points: up (a floor), down (a ceiling) or along.
enum class Facing { kUp, kDown, kSide };

Facing facing_of(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const double len = length(n);
  if (len == 0) return Facing::kSide;
  const double y = n.y / len;
  return y > 0.7 ? Facing::kUp : y < -0.7 ? Facing::kDown : Facing::kSide;
}

// The default reflectance of an element's faces when the model gives no colour.
double default_reflectance(const ModelElement& e, Facing facing) {
  if (is_furniture(e)) return kFurnitureReflectance;
  if (e.ifc_class == "IFCCOVERING") {
    if (e.predefined_type == "CEILING") return kCeilingReflectance;
    if (e.predefined_type == "FLOORING") return kFloorReflectance;
  }
  if (e.ifc_class == "IFCROOF") return kCeilingReflectance;
  if (is_slab(e) || e.ifc_class.empty() || e.ifc_class == "IFCCOVERING") {
    if (facing == Facing::kUp) return kFloorReflectance;
    if (facing == Facing::kDown) return kCeilingReflectance;
  }
  return kWallReflectance;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A file name from a material name: letters, digits and '-' only.
std::string file_stem(const std::string& name, std::size_t index) {
  std::string stem;
  for (const char c : lower(name)) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      stem += c;
    } else if (!stem.empty() && stem.back() != '-') {
      stem += '-';
    }
    if (stem.size() >= 40) break;
  }
  while (!stem.empty() && stem.back() == '-') stem.pop_back();
  return std::to_string(index) + (stem.empty() ? "" : "-" + stem);
}

// Names unique within one kind (portals, sensor sets, luminaires, objects): "NAME", "NAME 2", ...
class UniqueNames {
 public:
  std::string take(const std::string& wanted) {
    std::string name = wanted;
    for (int n = 2; !used_.insert(name).second; ++n) name = wanted + " " + std::to_string(n);
    return name;
  }

 private:
  std::set<std::string> used_;
};

std::string element_label(const ModelElement& e) {
  if (!e.long_name.empty()) return e.long_name;
  if (!e.name.empty()) return e.name;
  return lower(e.ifc_class.empty() ? "element" : e.ifc_class.substr(3)) + " #" +
         std::to_string(e.id);
}

// The scene's materials as the import builds them: one per (name, albedo), portals apart.
struct MaterialTable {
  struct Entry {
    std::string name;
    Rgb albedo;
    bool portal = false;
  };
  std::vector<Entry> entries;
  std::map<std::pair<std::string, std::array<long, 3>>, std::uint32_t> index;

  std::uint32_t opaque(const std::string& wanted, Rgb albedo) {
    const std::array<long, 3> key{std::lround(albedo.r * 1000), std::lround(albedo.g * 1000),
                                  std::lround(albedo.b * 1000)};
    const auto found = index.find({wanted, key});
    if (found != index.end()) return found->second;
    std::string name = wanted;
    for (int n = 2; std::any_of(entries.begin(), entries.end(),
                                [&](const Entry& e) { return e.name == name; });
         ++n)
      name = wanted + " " + std::to_string(n);
    entries.push_back({name, albedo, false});
    const auto id = static_cast<std::uint32_t>(entries.size() - 1);
    index[{wanted, key}] = id;
    return id;
  }
  std::uint32_t glass(const std::string& name) {
    entries.push_back({name, Rgb{0, 0, 0}, true});
    return static_cast<std::uint32_t>(entries.size() - 1);
  }
};

Rgb clamp_albedo(Rgb a) {
  const auto c = [](double x) { return std::clamp(x, 0.0, kMostReflectance); };
  return {c(a.r), c(a.g), c(a.b)};
}

// Appends a part's triangles to `soup` with material `material` (or, for an element without a
// colour, with the default material of each face's facing).
void append_part(TriangleSoup& soup, const ModelPart& part,
                 const std::function<std::uint32_t(Facing)>& material) {
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), part.positions.begin(), part.positions.end());
  for (const Triangle& t : part.triangles) {
    soup.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    soup.triangle_material.push_back(
        material(facing_of(part.positions[t[0]], part.positions[t[1]], part.positions[t[2]])));
  }
}

// The material of an opaque part: the model's colour, else the class default by facing.
std::function<std::uint32_t(Facing)> opaque_material(MaterialTable& materials,
                                                     const ModelElement& e, const ModelPart& part,
                                                     std::vector<std::string>& warnings) {
  if (part.albedo) {
    const Rgb albedo = clamp_albedo(*part.albedo);
    if (albedo.r != part.albedo->r || albedo.g != part.albedo->g || albedo.b != part.albedo->b) {
      static constexpr const char* kClamped =
          "colours lighter than a reflectance of 0.9 were taken as 0.9";
      if (std::find(warnings.begin(), warnings.end(), kClamped) == warnings.end())
        warnings.emplace_back(kClamped);
    }
    const std::string name = part.material_name.empty()
                                 ? lower(e.ifc_class.empty() ? "surface" : e.ifc_class.substr(3))
                                 : part.material_name;
    const std::uint32_t id = materials.opaque(name, albedo);
    return [id](Facing) { return id; };
  }
  return [&materials, &e](Facing facing) {
    const double rho = default_reflectance(e, facing);
    const char* kind = rho == kFloorReflectance       ? "floor"
                       : rho == kCeilingReflectance   ? "ceiling"
                       : rho == kFurnitureReflectance ? "furniture"
                                                      : "wall";
    return materials.opaque(std::string("default ") + kind, Rgb{rho, rho, rho});
  };
}

// Groups of triangles joined by shared corners (matched to 0.1 mm).
std::vector<std::vector<std::size_t>> connected_groups(const std::vector<Vec3>& positions,
                                                       const std::vector<Triangle>& triangles,
                                                       const std::vector<std::size_t>& subset) {
  std::map<std::array<long long, 3>, std::size_t> corner_group;
  std::vector<std::size_t> parent(subset.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < subset.size(); ++i)
    for (const std::uint32_t v : triangles[subset[i]]) {
      const Vec3 p = positions[v];
      const std::array<long long, 3> key{std::llround(p.x * 1e4), std::llround(p.y * 1e4),
                                         std::llround(p.z * 1e4)};
      const auto [it, added] = corner_group.try_emplace(key, i);
      if (!added) parent[root(i)] = root(it->second);
    }
  std::map<std::size_t, std::size_t> index;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < subset.size(); ++i) {
    const auto [it, added] = index.try_emplace(root(i), groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(subset[i]);
  }
  return groups;
}

// The glass triangles of a mesh file split into windows: groups joined by shared corners.
std::vector<TriangleSoup> split_windows(const ModelPart& part) {
  std::vector<std::size_t> all(part.triangles.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::vector<TriangleSoup> windows;
  for (const auto& group : connected_groups(part.positions, part.triangles, all)) {
    TriangleSoup& w = windows.emplace_back();
    for (const std::size_t t : group) {
      const auto base = static_cast<std::uint32_t>(w.positions.size());
      for (const std::uint32_t v : part.triangles[t]) w.positions.push_back(part.positions[v]);
      w.triangles.push_back({base, base + 1, base + 2});
      w.triangle_material.push_back(0);
    }
  }
  return windows;
}

// Writes one OBJ file per material of `soup` into `folder`; returns the scene's geometry entries.
Json write_meshes(const TriangleSoup& soup, const MaterialTable& materials, const fs::path& folder,
                  const std::string& prefix, const fs::path& scene_folder) {
  std::map<std::uint32_t, std::vector<std::size_t>> by_material;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    by_material[soup.triangle_material[t]].push_back(t);
  Json entries = Json::array();
  for (const auto& [m, triangles] : by_material) {
    std::ostringstream obj;
    obj.precision(9);
    std::map<std::uint32_t, std::uint32_t> local;
    std::ostringstream faces;
    for (const std::size_t t : triangles) {
      faces << 'f';
      for (const std::uint32_t v : soup.triangles[t]) {
        const auto [it, added] = local.try_emplace(v, static_cast<std::uint32_t>(local.size() + 1));
        if (added) {
          const Vec3 p = soup.positions[v];
          obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        }
        faces << ' ' << it->second;
      }
      faces << '\n';
    }
    obj << faces.str();
    const fs::path file = folder / (prefix + file_stem(materials.entries[m].name, m) + ".obj");
    write_text_atomically(file, obj.str());
    entries.push_back({{"type", "mesh"},
                       {"file", fs::relative(file, scene_folder).generic_string()},
                       {"material", materials.entries[m].name}});
  }
  return entries;
}

Json vec(Vec3 v) {
  const auto r = [](double x) { return std::round(x * 1e6) / 1e6; };
  return Json::array({r(v.x), r(v.y), r(v.z)});
}

// The storey the options name, or −1 for the whole model.
int chosen_storey(const BuildingModel& model, const ImportOptions& options) {
  if (!options.storey) return -1;
  const std::string& wanted = *options.storey;
  if (model.storeys.empty()) fail_input("--storey", "the model has no storeys");
  for (std::size_t i = 0; i < model.storeys.size(); ++i)
    if (model.storeys[i].name == wanted) return static_cast<int>(i);
  if (!wanted.empty() && std::all_of(wanted.begin(), wanted.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
      })) {
    const long n = std::strtol(wanted.c_str(), nullptr, 10);
    if (n >= 1 && n <= static_cast<long>(model.storeys.size())) return static_cast<int>(n - 1);
  }
  std::string names;
  for (std::size_t i = 0; i < model.storeys.size(); ++i)
    names += (i == 0 ? "" : ", ") + std::to_string(i + 1) + " \"" + model.storeys[i].name + "\"";
  fail_input("--storey " + wanted, "no such storey; the model's storeys from the lowest: " + names);
}

// The photometric file of a light fixture: the model's own, else the map's for its type name.
std::optional<fs::path> fixture_photometry(const ModelElement& e, const ImportOptions& options,
                                           const fs::path& model_file) {
  if (!e.photometry.empty()) {
    fs::path file = e.photometry;
    if (file.is_relative()) file = model_file.parent_path() / file;
    std::error_code ec;
    if (fs::is_regular_file(file, ec)) return file;
  }
  for (const std::string& key : {e.type_name, e.name}) {
    const auto found = options.photometry.find(key);
    if (!key.empty() && found != options.photometry.end()) return found->second;
  }
  return std::nullopt;
}

// The floors of a model without spaces: faces that point up with room above them (a surface
// facing down at least 2 m higher) and nothing facing up just below them (a table top has the
// floor below it), grouped into rooms by shared corners.
std::vector<std::vector<std::array<Vec3, 3>>> room_floors(const TriangleSoup& soup,
                                                          const std::vector<bool>& glass) {
  constexpr double kRoomHeight = 2.0;
  std::vector<std::uint32_t> ids(soup.triangles.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  const RayTracer tracer(soup.positions, soup.triangles, ids);
  // The first surface along a ray: whether it is glass, and whether the ray meets its front.
  struct Seen {
    double t = 0;
    bool glass = false, front = false;
  };
  const auto first_hit = [&](const Ray& ray) -> std::optional<Seen> {
    const RayHit hit = tracer.intersect(ray);
    if (!hit.hit()) return std::nullopt;
    const Triangle& t = soup.triangles[hit.triangle];
    const Vec3 n = cross(soup.positions[t[1]] - soup.positions[t[0]],
                         soup.positions[t[2]] - soup.positions[t[0]]);
    return Seen{hit.t, glass[soup.triangle_material[hit.triangle]], dot(n, ray.direction) < 0};
  };
  std::vector<std::size_t> floors;
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    const Triangle& t = soup.triangles[i];
    const Vec3 a = soup.positions[t[0]], b = soup.positions[t[1]], c = soup.positions[t[2]];
    if (glass[soup.triangle_material[i]] || facing_of(a, b, c) != Facing::kUp) continue;
    const Vec3 centre = (a + b + c) / 3.0;
    // A ceiling or a skylight above, high enough for a room.
    const auto above = first_hit({centre, {0, 1, 0}, 1e-6});
    if (!above || !(above->glass || above->front) || above->t < kRoomHeight) continue;
    const auto below = first_hit({centre, {0, -1, 0}, 1e-6});
    if (below && !below->glass && below->front) continue;
    floors.push_back(i);
  }
  std::vector<std::vector<std::array<Vec3, 3>>> rooms;
  for (const auto& group : connected_groups(soup.positions, soup.triangles, floors)) {
    std::vector<std::array<Vec3, 3>> room;
    for (const std::size_t i : group) {
      const Triangle& t = soup.triangles[i];
      room.push_back({soup.positions[t[0]], soup.positions[t[1]], soup.positions[t[2]]});
    }
    rooms.push_back(std::move(room));
  }
  return rooms;
}

}  // namespace

ImportSummary write_imported_scene(const BuildingModel& model, const ImportOptions& options,
                                   const fs::path& model_file, const fs::path& scene_file) {
  ImportSummary summary;
  const int storey = chosen_storey(model, options);
  summary.storeys = storey >= 0 ? 1 : static_cast<int>(model.storeys.size());
  const auto included = [&](const ModelElement& e) {
    if (storey < 0) return true;
    // The storey's own elements, and the slab above it: its ceiling.
    return e.storey == storey || (e.storey == storey + 1 && is_slab(e));
  };
  std::map<std::uint32_t, const ModelElement*> by_id;
  for (const ModelElement& e : model.elements) by_id[e.id] = &e;

  MaterialTable materials;
  TriangleSoup statics;
  UniqueNames portal_names, sensor_names, luminaire_names, object_names;
  Json portals = Json::array(), luminaires = Json::array(), objects_json = Json::array();
  std::vector<const ModelElement*> furniture;
  std::size_t dropped_glass = 0;
  std::vector<std::string> unlit_fixtures;
  const Json sky = {
      {"type", "cie_sky"}, {"sky_type", "overcast"}, {"horizontal_illuminance", kSkyIlluminance}};

  for (const ModelElement& e : model.elements) {
    if (!included(e) || is_not_surface(e)) continue;
    if (e.light_fixture) {
      if (const auto photometry = fixture_photometry(e, options, model_file)) {
        const std::string ext = lower(photometry->extension().string());
        luminaires.push_back(
            {{"name", luminaire_names.take(element_label(e))},
             {"position", vec(e.origin)},
             {"aim", vec(e.z_axis * -1.0)},
             {"c0", vec(e.x_axis)},
             {"distribution",
              {{"type", ext == ".ldt" ? "ldt" : "ies"},
               {"file", fs::absolute(*photometry)
                            .lexically_proximate(fs::absolute(scene_file).parent_path())
                            .generic_string()}}}});
        ++summary.luminaires;
        continue;  // the photometry includes the fixture's own body
      }
      unlit_fixtures.push_back(element_label(e) +
                               (e.type_name.empty() ? "" : " (type \"" + e.type_name + "\")"));
    }
    if (options.furniture_objects && is_furniture(e)) {
      furniture.push_back(&e);
      continue;
    }
    summary.windows += is_window(e) ? 1 : 0;
    summary.doors += is_door(e) ? 1 : 0;
    const ModelElement* parent =
        e.parent != 0 && by_id.contains(e.parent) ? by_id[e.parent] : nullptr;
    const bool glazing = is_window(e) || is_door(e) || e.ifc_class == "IFCCURTAINWALL" ||
                         (parent != nullptr && parent->ifc_class == "IFCCURTAINWALL");
    bool has_glass = false;
    std::optional<std::uint32_t> window_glass;
    for (const ModelPart& part : e.parts) {
      if (!part.transparent) {
        append_part(statics, part, opaque_material(materials, e, part, summary.warnings));
        continue;
      }
      if (e.ifc_class.empty()) {  // a mesh file's glass: one portal for each window it holds
        for (const TriangleSoup& w : split_windows(part)) {
          const std::string name =
              portal_names.take(part.material_name + " " + std::to_string(portals.size() + 1));
          const std::uint32_t m = materials.glass(name);
          ModelPart window{std::nullopt, true, name, w.positions, w.triangles};
          append_part(statics, window, [m](Facing) { return m; });
          portals.push_back({{"name", name}, {"material", name}, {"environment", sky}});
        }
        has_glass = true;
      } else if (glazing) {
        if (!window_glass) {  // every glass part of one window is one portal
          const std::string name = portal_names.take(element_label(e));
          window_glass = materials.glass(name);
          portals.push_back({{"name", name}, {"material", name}, {"environment", sky}});
        }
        const std::uint32_t m = *window_glass;
        append_part(statics, part, [m](Facing) { return m; });
        has_glass = true;
      } else {
        ++dropped_glass;  // see-through glass that is no window: light passes
      }
    }
    if (is_window(e) && !has_glass)
      summary.warnings.push_back("window " + element_label(e) +
                                 ": no glazing found, imported opaque");
  }
  summary.portals = static_cast<int>(portals.size());
  if (dropped_glass > 0)
    summary.warnings.push_back(
        std::to_string(dropped_glass) +
        " see-through parts that are not windows (glass railings, partitions) "
        "were left out: light passes them");
  for (const std::string& f : unlit_fixtures)
    summary.warnings.push_back("light fixture " + f +
                               ": no photometry in the model; give one with --photometry-map");
  if (statics.triangles.empty())
    fail_input(model_file.string(),
               "the model has no geometry" + std::string(storey >= 0 ? " on that storey" : ""));

  // Sensors: each space's floor (the bottom of its volume) at the work plane.
  Json sensors = Json::array();
  std::vector<AirSeed> seeds;
  std::set<std::string> wanted(options.spaces.begin(), options.spaces.end()), found;
  for (const ModelElement& e : model.elements) {
    if (!is_space(e) || !included(e)) continue;
    if (!wanted.empty() && !wanted.contains(e.name) && !wanted.contains(e.long_name)) continue;
    found.insert(e.name);
    found.insert(e.long_name);
    std::vector<std::array<Vec3, 3>> floor;
    double floor_y = std::numeric_limits<double>::infinity();
    for (const ModelPart& part : e.parts)
      for (const Triangle& t : part.triangles) {
        const std::array<Vec3, 3> tri{part.positions[t[0]], part.positions[t[1]],
                                      part.positions[t[2]]};
        if (facing_of(tri[0], tri[1], tri[2]) != Facing::kDown) continue;
        floor.push_back(tri);
        for (const Vec3& v : tri) floor_y = std::min(floor_y, v.y);
      }
    const std::string name = sensor_names.take(element_label(e));
    const std::vector<Vec3> points =
        floor_grid(floor, floor_y + options.work_plane, options.spacing, options.border);
    if (points.empty()) {
      char border[32];
      std::snprintf(border, sizeof border, "%g", options.border);
      summary.warnings.push_back("space " + name + ": no room for sensors inside its " + border +
                                 " m border");
      continue;
    }
    Json list = Json::array();
    for (const Vec3& p : points) {
      list.push_back(vec(p));
      seeds.push_back({p, {0, 1, 0}});
    }
    sensors.push_back({{"name", name}, {"points", list}, {"normal", {0, 1, 0}}});
    ++summary.spaces;
  }
  for (const std::string& w : wanted)
    if (!found.contains(w))
      fail_input("--space " + w, "no such space in the model (or on that storey)");

  // Faces that point out of the spaces they bound are turned before anything is written.
  std::vector<bool> glass;
  for (const auto& m : materials.entries) glass.push_back(m.portal);
  const SurfaceOrientation orientation = find_turned_surfaces(statics, glass, seeds);
  turn_triangles(statics, orientation.turned);
  const std::string orientation_note = orientation_warning(orientation);
  if (!orientation_note.empty()) summary.warnings.push_back(orientation_note);

  // A model without spaces: sensors on the floors of its rooms.
  if (seeds.empty()) {
    int room = 0;
    for (const auto& floor : room_floors(statics, glass)) {
      double floor_y = std::numeric_limits<double>::infinity();
      for (const auto& t : floor) floor_y = std::min({floor_y, t[0].y, t[1].y, t[2].y});
      const std::vector<Vec3> points =
          floor_grid(floor, floor_y + options.work_plane, options.spacing, options.border);
      if (points.empty()) continue;
      Json list = Json::array();
      for (const Vec3& p : points) list.push_back(vec(p));
      sensors.push_back({{"name", sensor_names.take("room " + std::to_string(++room))},
                         {"points", list},
                         {"normal", {0, 1, 0}}});
      ++summary.spaces;
    }
  }

  const fs::path scene_folder = fs::absolute(scene_file).parent_path();
  const fs::path mesh_folder = scene_folder / (scene_file.stem().string() + ".meshes");
  fs::create_directories(mesh_folder);
  Json geometry = write_meshes(statics, materials, mesh_folder, "", scene_folder);
  summary.triangles = statics.triangles.size();

  for (const ModelElement* e : furniture) {
    TriangleSoup soup;
    for (const ModelPart& part : e->parts) {
      if (part.transparent) continue;
      append_part(soup, part, opaque_material(materials, *e, part, summary.warnings));
    }
    if (soup.triangles.empty()) continue;
    const std::string name = object_names.take(element_label(*e));
    objects_json.push_back(
        {{"name", name},
         {"geometry", write_meshes(soup, materials, mesh_folder,
                                   "object-" + std::to_string(e->id) + "-", scene_folder)}});
    summary.triangles += soup.triangles.size();
    ++summary.objects;
  }

  Json scene;
  scene["description"] = "imported from " + model_file.filename().string() + " (" + model.format +
                         ") by relight import";
  Json materials_json = Json::object();
  for (const auto& m : materials.entries) {
    if (m.portal) {
      materials_json[m.name] = {{"portal", true}};
    } else {
      materials_json[m.name] = {
          {"albedo",
           {std::round(m.albedo.r * 1e4) / 1e4, std::round(m.albedo.g * 1e4) / 1e4,
            std::round(m.albedo.b * 1e4) / 1e4}}};
    }
  }
  scene["materials"] = materials_json;
  scene["geometry"] = geometry;
  if (!luminaires.empty()) scene["luminaires"] = luminaires;
  if (!sensors.empty()) scene["sensors"] = sensors;
  if (!portals.empty()) scene["portals"] = portals;
  if (!objects_json.empty()) scene["objects"] = objects_json;
  if (options.max_edge) scene["precompute"] = {{"max_edge", *options.max_edge}};
  if (model.site) {
    scene["site"] = {{"latitude", model.site->latitude},
                     {"longitude", model.site->longitude},
                     {"utc_offset", std::round(model.site->longitude / 15)},
                     {"elevation_m", model.site->elevation_m},
                     {"north_deg", std::round(model.site->north_deg * 1e6) / 1e6}};
  } else if (starts_with(model.format, "IFC")) {
    summary.warnings.push_back("the model's site gives no latitude and longitude: no site written");
  }
  if (sensors.empty())
    summary.warnings.push_back("no spaces with floors found: no sensors written");
  write_text_atomically(scene_file, scene.dump(2) + "\n");
  return summary;
}

std::string summary_json(const ImportSummary& s) {
  Json j;
  j["storeys"] = s.storeys;
  j["spaces"] = s.spaces;
  j["windows"] = s.windows;
  j["doors"] = s.doors;
  j["portals"] = s.portals;
  j["luminaires"] = s.luminaires;
  j["objects"] = s.objects;
  j["triangles"] = s.triangles;
  j["warnings"] = s.warnings;
  return j.dump();
}

std::map<std::string, fs::path> read_photometry_map(const fs::path& file) {
  Json doc;
  try {
    doc = Json::parse(read_file(file, 1U << 20));
  } catch (const Json::parse_error& e) {
    fail_input(file.string(), std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object())
    fail_input(file.string(), "a photometry map is a JSON object of type name → IES/LDT file");
  std::map<std::string, fs::path> map;
  for (const auto& [type, path] : doc.items()) {
    if (!path.is_string()) fail_input(file.string() + ":/" + type, "not a file name");
    fs::path photometry = path.get<std::string>();
    if (photometry.is_relative()) photometry = file.parent_path() / photometry;
    const std::string ext = lower(photometry.extension().string());
    if (ext != ".ies" && ext != ".ldt")
      fail_input(file.string() + ":/" + type, "not an .ies or .ldt file");
    std::error_code ec;
    if (!fs::is_regular_file(photometry, ec))
      fail_input(file.string() + ":/" + type, "no such file " + photometry.string());
    map[type] = photometry;
  }
  return map;
}

}  // namespace relight
