#include "scene/scene_loader.h"

#include <cmath>
#include <map>
#include <set>

#include "common/input_error.h"
#include "scene/mesh_import.h"
#include "scene/primitives.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

struct Loader {
  Scene scene;
  fs::path base_dir;
  const EmbeddedFiles* embedded = nullptr;
  std::map<std::string, std::uint32_t> material_index;

  std::uint32_t material_named(const JsonNode& node) {
    const std::string name = node.string();
    const auto it = material_index.find(name);
    if (it == material_index.end()) node.fail("unknown material \"" + name + "\"");
    return it->second;
  }

  std::uint32_t add_material(Material m) {
    const auto index = static_cast<std::uint32_t>(scene.materials.size());
    material_index.emplace(m.name, index);
    scene.materials.push_back(std::move(m));
    return index;
  }

  fs::path existing_file(const JsonNode& node) const {
    const fs::path relative = node.string();
    fs::path path = relative.is_absolute() ? relative : base_dir / relative;
    if (!fs::is_regular_file(path)) node.fail("file not found: " + path.string());
    return path;
  }

  void load_materials(const JsonNode& node) {
    if (!node.is_object()) node.fail("expected an object mapping names to materials");
    for (const auto& [name, unused] : node.value().items()) {
      const JsonNode m = node.at(name);
      m.expect_keys({"albedo", "portal", "metallic", "roughness", "glazing"});
      Material material{name};
      if (const auto portal = m.find("portal")) material.portal = portal->boolean();
      if (const auto g = m.find("glazing"); g && !material.portal) {
        g->fail("only window glass (\"portal\": true) has glazing");
      }
      if (material.portal) {
        // Window glass: its look is the portal's glazing, tint and frost, not a surface's.
        if (const auto a = m.find("albedo")) material.albedo = a->rgb_in_unit_range();
        if (const auto g = m.find("glazing")) material.glazing = parse_glazing(*g);
        for (const char* key : {"metallic", "roughness"}) {
          if (const auto k = m.find(key))
            k->fail("window glass (\"portal\": true) has no " + std::string(key));
        }
      } else {
        if (!m.has("albedo"))
          m.fail("missing required key \"albedo\" (only window glass may omit it)");
        read_reflectance(m, material);
      }
      add_material(std::move(material));
    }
  }

  static Facing facing(const JsonNode& g) {
    const auto n = g.find("normals");
    if (!n) return Facing::kOutward;
    const std::string s = n->string();
    if (s == "outward") return Facing::kOutward;
    if (s == "inward") return Facing::kInward;
    n->fail("expected \"inward\" or \"outward\", got \"" + s + "\"");
  }

  static Vec3 rotate_xyz(Vec3 p, Vec3 deg) {
    // Rotations about x, then y, then z (degrees, right-handed): R = Rz·Ry·Rx.
    const double cx = std::cos(radians(deg.x)), sx = std::sin(radians(deg.x));
    const double cy = std::cos(radians(deg.y)), sy = std::sin(radians(deg.y));
    const double cz = std::cos(radians(deg.z)), sz = std::sin(radians(deg.z));
    p = {p.x, cx * p.y - sx * p.z, sx * p.y + cx * p.z};
    p = {cy * p.x + sy * p.z, p.y, -sy * p.x + cy * p.z};
    return {cz * p.x - sz * p.y, sz * p.x + cz * p.y, p.z};
  }

  TriangleSoup load_mesh(const JsonNode& g) {
    g.expect_keys({"type", "file", "translate", "rotate_deg", "scale", "material"});
    const JsonNode file_node = g.at("file");
    const ImportedMesh mesh = import_mesh(existing_file(file_node));
    const Vec3 translate = g.find("translate") ? g.at("translate").vec3() : Vec3{};
    const Vec3 rotate = g.find("rotate_deg") ? g.at("rotate_deg").vec3() : Vec3{};
    Vec3 scale{1, 1, 1};
    if (const auto s = g.find("scale")) {
      if (s->value().is_array()) {
        scale = s->vec3();
        if (!(scale.x > 0 && scale.y > 0 && scale.z > 0)) s->fail("scale must be positive");
      } else {
        const double k = s->positive();
        scale = {k, k, k};
      }
    }
    TriangleSoup soup;
    soup.positions.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) {
      const Vec3 scaled{p.x * scale.x, p.y * scale.y, p.z * scale.z};
      soup.positions.push_back(rotate_xyz(scaled, rotate) + translate);
    }
    soup.triangles = mesh.triangles;
    if (const auto m = g.find("material")) {
      soup.triangle_material.assign(mesh.triangles.size(), material_named(*m));
    } else {
      // The file's own materials, named "FILE/NAME" in the scene.
      std::vector<std::uint32_t> remap;
      for (const ImportedMaterial& im : mesh.materials) {
        const std::string name = file_node.string() + "/" + im.name;
        const auto it = material_index.find(name);
        remap.push_back(
            it != material_index.end()
                ? it->second
                : add_material({name, im.albedo, false, im.glossy, im.metallic, im.roughness}));
      }
      soup.triangle_material.reserve(mesh.triangle_material.size());
      for (std::uint32_t m : mesh.triangle_material) soup.triangle_material.push_back(remap.at(m));
      soup.textures = mesh.textures;  // a scene material given instead has no texture
    }
    return soup;
  }

  void load_geometry(const JsonNode& node) {
    for (const JsonNode& g : node.elements()) scene.geometry.append(geometry_entry(g));
  }

  // What a lighting state turns a movable object about (exterior objects, emitters): the
  // centre of its bounding box. Fails at `where` for no triangles or a non-finite coordinate.
  static Vec3 movable_pivot(const TriangleSoup& geometry, const JsonNode& where,
                            const std::string& what) {
    if (geometry.triangles.empty()) where.fail(what + " has no triangles");
    Vec3 lo = geometry.positions.front(), hi = lo;
    for (const Vec3& p : geometry.positions) {
      if (!is_finite(p)) where.fail(what + " geometry has a non-finite coordinate");
      lo = min(lo, p);
      hi = max(hi, p);
    }
    return (lo + hi) * 0.5;
  }

  // Exterior entries are geometry entries with an optional "name".
  void load_exterior(const JsonNode& node) {
    std::set<std::string> names;
    for (const JsonNode& e : node.elements()) {
      ExteriorGeometry object;
      nlohmann::json entry = e.value();
      if (const auto n = e.find("name")) {
        object.name = n->string();
        if (object.name.empty()) n->fail("name must not be empty");
        if (!names.insert(object.name).second) {
          n->fail("duplicate exterior object \"" + object.name + "\"");
        }
        entry.erase("name");
      }
      object.geometry = geometry_entry(JsonNode(entry, e.file(), e.pointer()));
      for (std::uint32_t m : object.geometry.triangle_material) {
        if (scene.materials[m].portal) e.fail("exterior geometry cannot be window glass");
      }
      object.pivot = movable_pivot(object.geometry, e, "exterior object");
      scene.exterior.push_back(std::move(object));
    }
  }

  // Emitters: name, a geometry entry (its "material" may be left out: an emitter is not a
  // surface of the room), luminance in cd/m² (> 0) and a colour (luminance-normalised).
  void load_emitters(const JsonNode& node) {
    std::set<std::string> names;
    for (const JsonNode& e : node.elements()) {
      e.expect_keys({"name", "geometry", "luminance", "color"});
      Emitter emitter;
      emitter.name = e.at("name").string();
      if (emitter.name.empty()) e.at("name").fail("name must not be empty");
      if (!names.insert(emitter.name).second) {
        e.at("name").fail("duplicate emitter \"" + emitter.name + "\"");
      }
      const JsonNode g = e.at("geometry");
      if (!g.is_object()) g.fail("expected a geometry entry (quad, box, sphere or mesh)");
      nlohmann::json entry = g.value();
      if (!entry.contains("material")) entry["material"] = emitter_material();
      emitter.geometry = geometry_entry(JsonNode(entry, g.file(), g.pointer()));
      emitter.pivot = movable_pivot(emitter.geometry, g, "emitter");
      emitter.luminance = e.at("luminance").positive();
      if (const auto c = e.find("color")) {
        emitter.color = c->chromaticity();
      }
      scene.emitters.push_back(std::move(emitter));
    }
  }

  // Movable objects: a name (unique among objects, exterior objects and emitters, which share
  // the lighting state's placement rule) and a non-empty list of geometry entries.
  void load_objects(const JsonNode& node) {
    std::set<std::string> names;
    for (const ExteriorGeometry& x : scene.exterior) names.insert(x.name);
    for (const Emitter& e : scene.emitters) names.insert(e.name);
    for (const JsonNode& o : node.elements()) {
      o.expect_keys({"name", "geometry"});
      MovableObject object;
      object.name = o.at("name").string();
      if (object.name.empty()) o.at("name").fail("name must not be empty");
      if (!names.insert(object.name).second) {
        o.at("name").fail("the name \"" + object.name +
                          "\" is already used by an object, exterior object or emitter");
      }
      const JsonNode g = o.at("geometry");
      if (g.elements().empty()) g.fail("an object needs at least one geometry entry");
      for (const JsonNode& entry : g.elements()) object.geometry.append(geometry_entry(entry));
      for (std::uint32_t m : object.geometry.triangle_material) {
        if (scene.materials[m].portal) g.fail("an object cannot be window glass");
      }
      object.pivot = movable_pivot(object.geometry, g, "object");
      scene.objects.push_back(std::move(object));
    }
  }

  // The material emitter geometry gets when its entry names none (black, never in the room).
  std::string emitter_material() {
    static constexpr const char* kName = "emitter";
    if (!material_index.contains(kName)) add_material({kName, Rgb{0, 0, 0}, false});
    return kName;
  }

  TriangleSoup geometry_entry(const JsonNode& g) {
    TriangleSoup soup;
    {
      const std::string type = g.at("type").string();
      if (type == "quad") {
        g.expect_keys({"type", "corner", "u", "v", "material"});
        const Vec3 u = g.at("u").vec3(), v = g.at("v").vec3();
        if (length(cross(u, v)) < 1e-12) g.fail("quad edges u and v must span an area");
        soup = make_quad(g.at("corner").vec3(), u, v, material_named(g.at("material")));
      } else if (type == "box") {
        g.expect_keys({"type", "min", "max", "normals", "material"});
        const Vec3 lo = g.at("min").vec3(), hi = g.at("max").vec3();
        if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) {
          g.at("max").fail("box max must exceed min in every axis");
        }
        soup = make_box(lo, hi, facing(g), material_named(g.at("material")));
      } else if (type == "sphere") {
        g.expect_keys({"type", "center", "radius", "normals", "subdivisions", "material"});
        const int subdivisions = g.find("subdivisions") ? g.at("subdivisions").integer_in(0, 7) : 5;
        soup = make_sphere(g.at("center").vec3(), g.at("radius").positive(), facing(g),
                           subdivisions, material_named(g.at("material")));
      } else if (type == "mesh") {
        soup = load_mesh(g);
      } else {
        g.at("type").fail("unknown geometry type \"" + type +
                          "\" (expected quad, box, sphere or mesh)");
      }
    }
    return soup;
  }

  void load_luminaires(const JsonNode& node) {
    std::set<std::string> names;
    for (const JsonNode& l : node.elements()) {
      l.expect_keys({"name", "position", "aim", "c0", "color", "dimmer", "size", "distribution"});
      Luminaire lum;
      lum.where = l.where();
      lum.name = l.at("name").string();
      if (lum.name.empty()) l.at("name").fail("name must not be empty");
      if (!names.insert(lum.name).second)
        l.at("name").fail("duplicate luminaire \"" + lum.name + "\"");
      lum.position = l.at("position").vec3();
      if (const auto aim = l.find("aim")) lum.aim = aim->direction();
      const Vec3 hint = l.find("c0") ? l.at("c0").direction() : default_c0(lum.aim);
      const Vec3 c0 = hint - lum.aim * dot(hint, lum.aim);
      if (length(c0) < 1e-6) l.at("c0").fail("c0 must not be parallel to aim");
      lum.c0 = normalize(c0);
      if (const auto c = l.find("color")) {
        lum.color = c->chromaticity();
      }
      if (const auto d = l.find("dimmer")) lum.dimmer = d->number_at_least(0);
      if (const auto s = l.find("size")) {
        lum.size = s->vec3();
        if (lum.size.x < 0 || lum.size.y < 0 || lum.size.z < 0) {
          s->fail("size [width, length, height] must not be negative");
        }
        lum.has_size = true;
      }
      lum.distribution = parse_distribution(l.at("distribution"), base_dir, embedded);
      scene.luminaires.push_back(std::move(lum));
    }
  }

  static Vec3 default_c0(Vec3 aim) {
    // C0 along world +x, or -z for luminaires aimed along x.
    return std::abs(aim.x) > 0.999 ? Vec3{0, 0, -1} : Vec3{1, 0, 0};
  }

  void load_sensors(const JsonNode& node) {
    std::set<std::string> names;
    for (const JsonNode& s : node.elements()) {
      s.expect_keys({"name", "grid", "points", "normal", "task"});
      SensorSet set;
      if (const auto t = s.find("task")) set.task = parse_task(*t);
      set.name = s.at("name").string();
      if (!names.insert(set.name).second)
        s.at("name").fail("duplicate sensor set \"" + set.name + "\"");
      if (const auto n = s.find("normal")) set.normal = n->direction();
      const bool grid = s.has("grid"), points = s.has("points");
      if (grid == points) s.fail("a sensor set needs exactly one of \"grid\" or \"points\"");
      if (grid) {
        const JsonNode g = s.at("grid");
        g.expect_keys({"corner", "u", "v", "nu", "nv"});
        const Vec3 corner = g.at("corner").vec3(), u = g.at("u").vec3(), v = g.at("v").vec3();
        set.nu = g.at("nu").integer_in(1, 100000);
        set.nv = g.at("nv").integer_in(1, 100000);
        if (static_cast<long long>(set.nu) * set.nv > 50'000'000)
          g.fail("grid has too many points");
        for (int j = 0; j < set.nv; ++j) {
          for (int i = 0; i < set.nu; ++i) {
            set.points.push_back(corner + u * ((i + 0.5) / set.nu) + v * ((j + 0.5) / set.nv));
          }
        }
      } else {
        for (const JsonNode& p : s.at("points").elements()) set.points.push_back(p.vec3());
        if (set.points.empty()) s.at("points").fail("expected at least one point");
      }
      scene.sensors.push_back(std::move(set));
    }
  }

  static TaskRequirements parse_task(const JsonNode& t) {
    if (!t.is_object()) t.fail("expected an object");
    t.expect_keys({"em", "u0", "ugr_l", "observers"});
    TaskRequirements task;
    if (const auto e = t.find("em")) task.em = e->number_at_least(0);
    if (const auto u = t.find("u0")) {
      task.u0 = u->number_at_least(0);
      if (*task.u0 > 1) u->fail("u0 is a ratio Emin/Eavg in 0..1");
    }
    if (const auto g = t.find("ugr_l")) task.ugr_l = g->number_at_least(0);
    if (const auto o = t.find("observers")) {
      for (const JsonNode& obs : o->elements()) {
        obs.expect_keys({"position", "view"});
        task.observers.push_back({obs.at("position").vec3(), obs.at("view").direction()});
      }
    }
    if (task.ugr_l && task.observers.empty()) {
      t.at("ugr_l").fail("a UGR limit needs \"observers\": [{\"position\", \"view\"}, ...]");
    }
    if (!task.em && !task.u0 && !task.ugr_l) t.fail("give at least one of em, u0, ugr_l");
    return task;
  }

  void load_cameras(const JsonNode& node) {
    std::set<std::string> names;
    for (const JsonNode& c : node.elements()) {
      c.expect_keys({"name", "eye", "target", "up", "fov_deg"});
      Camera cam;
      cam.name = c.at("name").string();
      if (!names.insert(cam.name).second)
        c.at("name").fail("duplicate camera \"" + cam.name + "\"");
      cam.eye = c.at("eye").vec3();
      cam.target = c.at("target").vec3();
      if (length(cam.target - cam.eye) < 1e-9) c.at("target").fail("target must differ from eye");
      if (const auto up = c.find("up")) cam.up = up->direction();
      if (length(cross(cam.up, cam.target - cam.eye)) < 1e-9)
        c.at("up").fail("up is parallel to the view direction");
      if (const auto f = c.find("fov_deg")) {
        cam.fov_deg = f->positive();
        if (cam.fov_deg >= 180) f->fail("fov_deg must be below 180");
      }
      scene.cameras.push_back(std::move(cam));
    }
  }

  const Site* site() const { return scene.site ? &*scene.site : nullptr; }

  void load_portals(const JsonNode& node) {
    std::set<std::string> names;
    std::map<std::uint32_t, std::string> owner;  // portal material -> portal
    for (const JsonNode& p : node.elements()) {
      p.expect_keys({"name", "material", "materials", "environment", "tint", "frost_deg",
                     "exterior_distance", "shell_tolerance_deg"});
      Portal portal;
      portal.name = p.at("name").string();
      if (portal.name.empty()) p.at("name").fail("name must not be empty");
      if (!names.insert(portal.name).second) {
        p.at("name").fail("duplicate portal \"" + portal.name + "\"");
      }
      if (p.has("material") == p.has("materials")) {
        p.fail("a portal needs exactly one of \"material\" or \"materials\"");
      }
      std::vector<JsonNode> material_nodes;
      if (p.has("material")) {
        material_nodes.push_back(p.at("material"));
      } else {
        material_nodes = p.at("materials").elements();
        if (material_nodes.empty()) p.at("materials").fail("expected at least one material");
      }
      for (const JsonNode& m : material_nodes) {
        const std::uint32_t index = material_named(m);
        if (!scene.materials[index].portal) {
          m.fail("material \"" + scene.materials[index].name +
                 "\" is not window glass: give it \"portal\": true");
        }
        const auto [it, fresh] = owner.emplace(index, portal.name);
        if (!fresh) {
          m.fail("material \"" + scene.materials[index].name + "\" already belongs to portal \"" +
                 it->second + "\"");
        }
        portal.materials.push_back(index);
        if (portal.materials.size() == 1) {
          portal.glazing = scene.materials[index].glazing;
        } else if (scene.materials[index].glazing != portal.glazing) {
          m.fail("the materials of portal \"" + portal.name +
                 "\" have different glazing: give them the same, or make them two portals");
        }
      }
      portal.environment =
          parse_environment(p.at("environment"), base_dir, embedded == nullptr, site());
      if (const auto t = p.find("tint")) portal.tint = parse_tint(*t);
      if (const auto f = p.find("frost_deg")) portal.frost_deg = parse_frost_deg(*f);
      if (const auto d = p.find("exterior_distance"))
        portal.exterior_distance = d->number_at_least(0);
      if (const auto t = p.find("shell_tolerance_deg")) {
        portal.shell_tolerance_deg = t->positive();
        if (portal.shell_tolerance_deg >= 90) t->fail("shell_tolerance_deg must be below 90");
      }
      scene.portals.push_back(std::move(portal));
    }
  }

  void load_precompute(const JsonNode& p) {
    p.expect_keys({"max_edge", "sh_order", "crease_deg", "gather_rays", "sensor_gather_rays",
                   "tolerance", "max_bounces", "direct", "portal_face_size", "portal_sh_order",
                   "portal_samples_per_cell", "nearfield_sh_order", "nearfield_directions",
                   "nearfield_interreflection", "nearfield_shadow_distance", "storage", "cuts",
                   "runtime_bounce"});
    PrecomputeSettings& s = scene.precompute;
    if (const auto n = p.find("max_edge")) s.max_edge = n->positive();
    if (const auto n = p.find("sh_order")) s.sh_order = n->integer_in(1, 32);
    if (const auto n = p.find("crease_deg")) {
      s.crease_deg = n->number_at_least(0);
      if (s.crease_deg > 180) n->fail("crease_deg must be at most 180");
    }
    if (const auto n = p.find("gather_rays")) s.gather_rays = n->integer_in(1, 1 << 20);
    if (const auto n = p.find("sensor_gather_rays")) {
      s.sensor_gather_rays = n->integer_in(1, 1 << 24);
    }
    if (const auto n = p.find("tolerance")) s.tolerance = n->positive();
    if (const auto n = p.find("max_bounces")) s.max_bounces = n->integer_in(0, 100000);
    if (const auto n = p.find("direct")) {
      s.direct = n->string();
      if (s.direct != "exact" && s.direct != "sh") n->fail("expected \"exact\" or \"sh\"");
    }
    if (const auto n = p.find("storage")) {
      s.storage = n->string();
      if (s.storage != "fp16" && s.storage != "fp32") n->fail("expected \"fp16\" or \"fp32\"");
    }
    if (const auto n = p.find("nearfield_sh_order")) s.nearfield_sh_order = n->integer_in(1, 16);
    if (const auto n = p.find("nearfield_directions")) {
      s.nearfield_directions = n->integer_in(1, 1 << 20);
      const int root = static_cast<int>(std::lround(std::sqrt(s.nearfield_directions)));
      if (root * root != s.nearfield_directions) {
        n->fail("nearfield_directions must be a square number (a stratified √N × √N grid)");
      }
    }
    if (const auto n = p.find("nearfield_shadow_distance")) {
      s.nearfield_shadow_distance = n->number_at_least(0);
    }
    if (const auto n = p.find("nearfield_interreflection")) {
      s.nearfield_interreflection = n->boolean();
    }
    if (const auto n = p.find("runtime_bounce")) s.runtime_bounce = n->boolean();
    if (const auto n = p.find("portal_face_size")) {
      s.portal_face_size = n->integer_in(1, 256);
      if ((s.portal_face_size & (s.portal_face_size - 1)) != 0) {
        n->fail("portal_face_size must be a power of two (the per-face Haar transform)");
      }
    }
    if (const auto n = p.find("portal_sh_order")) s.portal_sh_order = n->integer_in(1, 16);
    if (const auto n = p.find("portal_samples_per_cell")) {
      s.portal_samples_per_cell = n->integer_in(1, 1024);
    }
    if (const auto c = p.find("cuts")) load_cuts(*c, s.cuts);
  }

  static void load_cuts(const JsonNode& c, CutsSettings& s) {
    c.expect_keys({"directions", "sphere_count", "sphere_points", "inner_radius", "outer_radius",
                   "threshold"});
    if (const auto n = c.find("directions")) {
      s.directions = n->integer_in(4, 1 << 15);
      if ((s.directions & (s.directions - 1)) != 0) {
        n->fail("directions must be a power of two (the leaves of a complete binary tree)");
      }
    }
    if (const auto n = c.find("sphere_count")) s.sphere_count = n->integer_in(1, 256);
    if (const auto n = c.find("sphere_points")) s.sphere_points = n->integer_in(1, 256);
    if (const auto n = c.find("inner_radius")) {
      s.inner_radius = n->positive();
      if (s.inner_radius < 1) n->fail("inner_radius must be at least 1 (the bounding sphere)");
    }
    if (const auto n = c.find("outer_radius")) {
      s.outer_radius = n->positive();
      if (s.outer_radius < s.inner_radius) n->fail("outer_radius must be at least inner_radius");
    }
    if (const auto n = c.find("threshold")) {
      s.threshold = n->number_at_least(0);
      if (s.threshold >= 0.5) {
        n->fail(
            "threshold must be below 0.5 (the fraction of a node's directions whose "
            "visibility may differ from the rest)");
      }
    }
  }
};

}  // namespace

DistributionSpec parse_distribution(const JsonNode& node, const fs::path& base_dir,
                                    const EmbeddedFiles* embedded) {
  DistributionSpec d;
  d.where = node.where();
  const std::string type = node.at("type").string();
  auto resolve = [&](const JsonNode& f) {
    const fs::path relative = f.string();
    fs::path path = relative.is_absolute() ? relative : base_dir / relative;
    if (embedded) {
      const auto it = embedded->find(path.string());
      if (it != embedded->end()) {
        d.contents = it->second;
        return path;
      }
    }
    if (!fs::is_regular_file(path)) f.fail("file not found: " + path.string());
    return path;
  };
  if (type == "isotropic") {
    node.expect_keys({"type", "candela"});
    d.type = DistributionType::kIsotropic;
    d.candela = node.at("candela").number_at_least(0);
  } else if (type == "cosine_power") {
    node.expect_keys({"type", "candela", "exponent", "cutoff_deg"});
    d.type = DistributionType::kCosinePower;
    d.candela = node.at("candela").number_at_least(0);
    d.exponent = node.at("exponent").number_at_least(0);
    if (const auto c = node.find("cutoff_deg")) {
      d.cutoff_deg = c->positive();
      if (d.cutoff_deg > 180) c->fail("cutoff_deg must be at most 180");
    }
  } else if (type == "curve") {
    node.expect_keys({"type", "gamma_deg", "candela"});
    d.type = DistributionType::kCurve;
    d.gamma_deg = node.at("gamma_deg").numbers();
    d.curve_candela = node.at("candela").numbers();
    if (d.gamma_deg.size() < 2) node.at("gamma_deg").fail("expected at least 2 control points");
    if (d.gamma_deg.size() != d.curve_candela.size()) {
      node.at("candela").fail("expected as many values as gamma_deg (" +
                              std::to_string(d.gamma_deg.size()) + ")");
    }
    if (d.gamma_deg.front() != 0) node.at("gamma_deg").fail("the first control point must be at 0");
    for (std::size_t i = 1; i < d.gamma_deg.size(); ++i) {
      if (!(d.gamma_deg[i] > d.gamma_deg[i - 1])) node.at("gamma_deg").fail("angles must ascend");
    }
    if (d.gamma_deg.back() > 180) node.at("gamma_deg").fail("angles must not exceed 180");
    for (double c : d.curve_candela) {
      if (c < 0) node.at("candela").fail("intensities must not be negative");
    }
  } else if (type == "ies" || type == "ldt") {
    node.expect_keys({"type", "file"});
    d.type = type == "ies" ? DistributionType::kIes : DistributionType::kLdt;
    d.file = resolve(node.at("file"));
  } else {
    node.at("type").fail("unknown distribution type \"" + type +
                         "\" (expected isotropic, cosine_power, curve, ies or ldt)");
  }
  return d;
}

Scene scene_from_json(const nlohmann::json& document, const fs::path& file,
                      const EmbeddedFiles* embedded, const std::vector<Material>* materials) {
  const JsonNode root(document, file.string(), "/");
  root.expect_keys({"description", "materials", "geometry", "luminaires", "sensors", "cameras",
                    "portals", "exterior", "emitters", "objects", "precompute",
                    "maintenance_factor", "environment", "site"});
  Loader loader;
  loader.scene.file = file;
  loader.base_dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  loader.embedded = embedded;
  if (const auto n = root.find("description")) n->string();
  if (const auto n = root.find("site")) loader.scene.site = parse_site(*n);
  if (materials != nullptr) {
    for (const Material& m : *materials) loader.add_material(m);
  } else if (const auto n = root.find("materials")) {
    loader.load_materials(*n);
  }
  if (const auto n = root.find("geometry")) loader.load_geometry(*n);
  if (const auto n = root.find("luminaires")) loader.load_luminaires(*n);
  if (const auto n = root.find("sensors")) loader.load_sensors(*n);
  if (const auto n = root.find("cameras")) loader.load_cameras(*n);
  if (const auto n = root.find("portals")) loader.load_portals(*n);
  if (const auto n = root.find("environment")) {
    loader.scene.environment =
        parse_environment(*n, loader.base_dir, embedded == nullptr, loader.site());
  }
  if (const auto n = root.find("exterior")) loader.load_exterior(*n);
  if (const auto n = root.find("emitters")) loader.load_emitters(*n);
  if (const auto n = root.find("objects")) loader.load_objects(*n);
  if (const auto n = root.find("precompute")) {
    loader.load_precompute(*n);
    const Scene& sc = loader.scene;
    if (!sc.precompute.runtime_bounce &&
        (!sc.portals.empty() || !sc.emitters.empty() || !sc.objects.empty() || sc.environment)) {
      n->at("runtime_bounce")
          .fail(
              "portals, emitters, movable objects and a top-level environment bounce their light "
              "through the gather operator at run time: it cannot be left out of this scene");
    }
  }
  if (const auto n = root.find("maintenance_factor")) {
    const double mf = n->number_at_least(0);
    if (!(mf > 0 && mf <= 1)) n->fail("a maintenance factor lies in (0, 1]");
    loader.scene.maintenance_factor = mf;
  }
  for (const Vec3& p : loader.scene.geometry.positions) {
    if (!is_finite(p)) root.at("geometry").fail("geometry has a non-finite coordinate");
  }
  return std::move(loader.scene);
}

Scene load_scene(const fs::path& file) {
  return scene_from_json(read_json_file(file), file);
}

void read_reflectance(const JsonNode& node, Material& material) {
  if (const auto a = node.find("albedo")) material.albedo = a->rgb_in_unit_range();
  if (const auto metallic = node.find("metallic")) {
    material.glossy = true;
    material.metallic = metallic->unit_interval();
  }
  if (const auto roughness = node.find("roughness")) {
    material.glossy = true;
    material.roughness = roughness->unit_interval();
  }
}

}  // namespace relight
