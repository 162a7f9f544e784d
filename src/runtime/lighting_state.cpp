#include "runtime/lighting_state.h"

#include <cmath>
#include <stdexcept>

#include "common/input_error.h"
#include "light/color_temperature.h"
#include "light/luminaire_frame.h"
#include "scene/json_node.h"
#include "scene/scene_loader.h"

namespace relight {

namespace {

// The state's luminaire of that name (the scene's, then those the state added), or none.
LuminaireState* find_luminaire(LightingState& state, const std::string& name) {
  for (LuminaireState& l : state.luminaires) {
    if (l.name == name) return &l;
  }
  return nullptr;
}

void apply_luminaire(LuminaireState& s, const Scene& scene, const JsonNode& node,
                     const std::filesystem::path& base_dir) {
  node.expect_keys({"on", "dimmer", "color", "cct_kelvin", "aim", "target", "c0", "distribution",
                    "position", "size"});
  if (const auto p = node.find("position")) {
    const Vec3 at = p->vec3();
    // Named as docs/lighting-state.md names it: STATE:luminaires.NAME.position.
    if (!contains(scene.bounds(), at)) {
      fail_input(p->file() + ":luminaires." + s.name + ".position", "outside the scene");
    }
    s.position = at;
  }
  if (const auto z = node.find("size")) {
    s.size = z->vec3();
    if (s.size.x < 0 || s.size.y < 0 || s.size.z < 0) {
      z->fail("size [width, length, height] must not be negative");
    }
    s.has_size = true;
  }
  if (const auto on = node.find("on")) s.on = on->boolean();
  if (const auto d = node.find("dimmer")) s.dimmer = d->number_at_least(0);
  if (node.has("color") && node.has("cct_kelvin")) node.fail("give either color or cct_kelvin");
  if (const auto c = node.find("color")) {
    s.color = c->chromaticity();
  }
  if (const auto k = node.find("cct_kelvin")) {
    const double kelvin = k->number();
    if (kelvin < kMinCctKelvin || kelvin > kMaxCctKelvin) {
      k->fail("colour temperature must lie in 1667..25000 K");
    }
    s.color = cct_to_rgb(kelvin);
  }
  if (node.has("aim") && node.has("target")) node.fail("give either aim or target");
  if (const auto a = node.find("aim")) s.aim = a->direction();
  if (const auto t = node.find("target")) {
    const Vec3 d = t->vec3() - s.position;
    if (length(d) < 1e-9) t->fail("target coincides with the luminaire");
    s.aim = normalize(d);
  }
  if (const auto c = node.find("c0")) {
    s.c0 = c->direction();
    if (length(cross(s.c0, s.aim)) < 1e-6) c->fail("c0 must not be parallel to aim");
  }
  s.c0 = reorthogonalised_c0(s.c0, s.aim);
  if (const auto d = node.find("distribution")) s.distribution = parse_distribution(*d, base_dir);
}

std::size_t exterior_index(const Scene& scene, const JsonNode& where, const std::string& name) {
  for (std::size_t i = 0; i < scene.exterior.size(); ++i) {
    if (scene.exterior[i].name == name) return i;
  }
  where.fail("no exterior object named \"" + name + "\" in the precomputed scene");
}

// "translate" and "rotate_deg" of an object's entry (math/placement.h).
void apply_placement(Placement& p, const JsonNode& node) {
  if (const auto t = node.find("translate")) p.translate = t->vec3();
  if (const auto r = node.find("rotate_deg")) p.rotate_deg = r->number();
}

void apply_movable_placement(MovablePlacement& p, const JsonNode& node) {
  node.expect_keys({"translate", "rotate_deg", "visible"});
  apply_placement(p, node);
  if (const auto v = node.find("visible")) p.visible = v->boolean();
}

// Applies an "exterior" object (names → placements) to every portal in `portals`.
void apply_exterior(const std::vector<PortalState*>& portals, const Scene& scene,
                    const JsonNode& node) {
  if (!node.is_object())
    node.fail("expected an object mapping exterior object names to placements");
  for (const auto& [name, unused] : node.value().items()) {
    const JsonNode entry = node.at(name);
    const std::size_t i = exterior_index(scene, entry, name);
    for (PortalState* p : portals) apply_movable_placement(p->exterior[i], entry);
  }
}

std::size_t portal_index(const Scene& scene, const JsonNode& where, const std::string& name) {
  for (std::size_t i = 0; i < scene.portals.size(); ++i) {
    if (scene.portals[i].name == name) return i;
  }
  where.fail("no portal named \"" + name + "\" in the precomputed scene");
}

std::size_t object_index(const Scene& scene, const JsonNode& where, const std::string& name) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name == name) return i;
  }
  where.fail("no movable object named \"" + name + "\" in the precomputed scene");
}

std::size_t emitter_index(const Scene& scene, const JsonNode& where, const std::string& name) {
  for (std::size_t i = 0; i < scene.emitters.size(); ++i) {
    if (scene.emitters[i].name == name) return i;
  }
  where.fail("no emitter named \"" + name + "\" in the precomputed scene");
}

std::size_t material_index(const Scene& scene, const JsonNode& where, const std::string& name) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return i;
  }
  where.fail("no material named \"" + name + "\" in the precomputed scene");
}

// A material edit: the scene's own keys and rules (scene/scene_loader.h read_reflectance).
void apply_material(Material& m, const JsonNode& node) {
  if (!node.is_object()) node.fail("expected a material: albedo, metallic, roughness");
  node.expect_keys({"albedo", "metallic", "roughness"});
  if (m.portal) {
    node.fail("\"" + m.name + "\" is window glass: its look is its portal's tint and frost");
  }
  read_reflectance(node, m);
}

void apply_emitter(EmitterState& e, const JsonNode& node) {
  node.expect_keys({"translate", "rotate_deg", "luminance", "color", "on"});
  apply_placement(e, node);
  if (const auto l = node.find("luminance")) e.luminance = l->number_at_least(0);
  if (const auto c = node.find("color")) {
    e.color = c->chromaticity();
  }
  if (const auto o = node.find("on")) e.on = o->boolean();
}

void apply_portal(PortalState& s, const Scene& scene, const JsonNode& node,
                  const std::filesystem::path& base_dir, const Site* site) {
  node.expect_keys({"environment", "tint", "frost_deg", "glazing", "exterior"});
  if (const auto e = node.find("environment")) {
    s.environment = parse_environment(*e, base_dir, true, site);
  }
  if (const auto t = node.find("tint")) s.tint = parse_tint(*t);
  if (const auto f = node.find("frost_deg")) s.frost_deg = parse_frost_deg(*f);
  if (const auto g = node.find("glazing")) s.glazing = parse_glazing(*g);
  if (const auto x = node.find("exterior")) apply_exterior({&s}, scene, *x);
}

}  // namespace

void apply_lighting_state(LightingState& state, const Scene& scene, const nlohmann::json& document,
                          const std::string& where, const std::filesystem::path& base_dir) {
  const JsonNode root(document, where, "/");
  root.expect_keys({"luminaires", "portals", "exterior", "emitters", "objects", "materials",
                    "environment", "site"});
  // The site first: every environment, the state's so far and those it sets, stands there.
  if (const auto n = root.find("site")) {
    state.site = parse_site(*n);
    for (PortalState& p : state.portals) apply_site(p.environment, *state.site);
    if (state.environment) apply_site(*state.environment, *state.site);
  }
  const Site* site = state.site ? &*state.site : nullptr;
  if (const auto e = root.find("environment")) {
    if (!scene.environment) {
      e->fail(
          "the scene has no top-level environment: its transfer has no visibility cuts to "
          "light one (add \"environment\" to the scene and run relight precompute)");
    }
    state.environment = parse_environment(*e, base_dir, true, site);
  }
  if (state.materials.size() != scene.materials.size()) state.materials = scene.materials;
  if (const auto materials = root.find("materials")) {
    if (!materials->is_object())
      materials->fail("expected an object mapping material names to materials");
    for (const auto& [name, unused] : materials->value().items()) {
      const JsonNode node = materials->at(name);
      apply_material(state.materials[material_index(scene, node, name)], node);
    }
  }
  if (const auto lums = root.find("luminaires")) {
    if (!lums->is_object()) lums->fail("expected an object mapping luminaire names to states");
    for (const auto& [name, unused] : lums->value().items()) {
      const JsonNode node = lums->at(name);
      LuminaireState* s = find_luminaire(state, name);
      if (s == nullptr) {
        // A luminaire the scene does not have: the layout adds it.
        if (name.empty()) node.fail("a luminaire's name must not be empty");
        for (const char* key : {"position", "distribution"}) {
          if (node.is_object() && !node.has(key)) {
            node.fail("no luminaire named \"" + name +
                      "\" in the precomputed scene: a luminaire the state adds needs \"" + key +
                      "\"");
          }
        }
        LuminaireState added;
        added.name = name;
        state.luminaires.push_back(std::move(added));
        s = &state.luminaires.back();
      }
      apply_luminaire(*s, scene, node, base_dir);
    }
  }
  // The top-level exterior first: a portal's own "exterior" overrides it for its shell.
  if (const auto x = root.find("exterior")) {
    std::vector<PortalState*> all;
    for (PortalState& p : state.portals) all.push_back(&p);
    apply_exterior(all, scene, *x);
  }
  if (const auto emitters = root.find("emitters")) {
    if (!emitters->is_object())
      emitters->fail("expected an object mapping emitter names to states");
    for (const auto& [name, unused] : emitters->value().items()) {
      const JsonNode node = emitters->at(name);
      apply_emitter(state.emitters[emitter_index(scene, node, name)], node);
    }
  }
  if (const auto objects = root.find("objects")) {
    if (!objects->is_object())
      objects->fail("expected an object mapping object names to placements");
    for (const auto& [name, unused] : objects->value().items()) {
      const JsonNode node = objects->at(name);
      if (!node.is_object()) node.fail("expected a placement: translate, rotate_deg, visible");
      apply_movable_placement(state.objects[object_index(scene, node, name)], node);
    }
  }
  if (const auto portals = root.find("portals")) {
    if (!portals->is_object()) portals->fail("expected an object mapping portal names to states");
    for (const auto& [name, unused] : portals->value().items()) {
      const JsonNode node = portals->at(name);
      const std::size_t i = portal_index(scene, node, name);
      apply_portal(state.portals[i], scene, node, base_dir, site);
    }
  }
}

LightingState load_lighting_state(const Scene& scene, const std::filesystem::path& file) {
  LightingState state = default_lighting_state(scene);
  apply_lighting_state(state, scene, read_json_file(file), file.string(),
                       file.has_parent_path() ? file.parent_path() : std::filesystem::path("."));
  return state;
}

LightingState maintained_state(LightingState state, double mf) {
  for (LuminaireState& l : state.luminaires) l.dimmer *= mf;
  for (EmitterState& e : state.emitters) e.luminance *= mf;
  return state;
}

Scene scene_with_state(const Scene& scene, const LightingState& state) {
  if (state.luminaires.size() < scene.luminaires.size() ||
      state.portals.size() != scene.portals.size()) {
    throw std::invalid_argument("scene_with_state: the state is not of this scene");
  }
  Scene out = scene;
  // The scene's luminaires where the state moved them, then those it added.
  out.luminaires.clear();
  for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
    out.luminaires.push_back(scene_luminaire(state.luminaires[j]));
    if (j < scene.luminaires.size()) out.luminaires.back().where = scene.luminaires[j].where;
  }
  if (state.objects.size() != scene.objects.size()) {
    throw std::invalid_argument("scene_with_state: the state is not of this scene");
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (state.objects[i].visible) {
      out.geometry.append(
          placed_geometry(scene.objects[i].geometry, scene.objects[i].pivot, state.objects[i]));
    }
  }
  out.objects.clear();
  if (state.materials.size() == scene.materials.size()) out.materials = state.materials;
  for (std::size_t p = 0; p < out.portals.size(); ++p) {
    out.portals[p].environment = state.portals[p].environment;
    out.portals[p].tint = state.portals[p].tint;
    out.portals[p].frost_deg = state.portals[p].frost_deg;
    out.portals[p].glazing = state.portals[p].glazing;
  }
  out.environment = state.environment;
  return out;
}

}  // namespace relight
