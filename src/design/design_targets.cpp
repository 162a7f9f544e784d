#include "design/design_targets.h"

#include <algorithm>
#include <optional>

#include "scene/json_node.h"

namespace relight {

namespace {

// Whether `key` is a JSON member of the sensor-set entry and its number (lx ≥ 0; U0 in 0..1).
std::optional<double> target_value(const JsonNode& set, TargetKind kind) {
  const auto node = set.find(target_key(kind));
  if (!node) return std::nullopt;
  return kind == TargetKind::kU0Min ? node->unit_interval() : node->number_at_least(0);
}

void read_set_targets(const JsonNode& node, std::size_t set, DesignTargets& out) {
  node.expect_keys({"em_min", "em_max", "u0_min", "e_min", "e_max"});
  std::optional<double> values[std::size(kTargetKinds)];
  for (std::size_t k = 0; k < std::size(kTargetKinds); ++k) {
    values[k] = target_value(node, kTargetKinds[k]);
    if (values[k]) out.targets.push_back({set, kTargetKinds[k], *values[k]});
  }
  const auto check_order = [&](TargetKind lo, TargetKind hi) {
    const auto& a = values[static_cast<std::size_t>(lo)];
    const auto& b = values[static_cast<std::size_t>(hi)];
    if (a && b && *a > *b) {
      node.at(target_key(lo))
          .fail(std::string("is above ") + target_key(hi) + " (" + std::to_string(*b) + ")");
    }
  };
  check_order(TargetKind::kEmMin, TargetKind::kEmMax);
  check_order(TargetKind::kEMin, TargetKind::kEMax);
}

std::size_t set_index(const Scene& scene, const JsonNode& node, const std::string& name) {
  for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
    if (scene.sensors[s].name == name) return s;
  }
  node.fail("no sensor set named \"" + name + "\" in the precomputed scene");
}

std::size_t luminaire_index(const Scene& scene, const JsonNode& node, const std::string& name) {
  for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
    if (scene.luminaires[i].name == name) return i;
  }
  node.fail("no luminaire named \"" + name + "\" in the precomputed scene");
}

void read_freedom(const JsonNode& node, LuminaireFreedom& l) {
  node.expect_keys({"dimmer", "aim_cone_deg", "fixed"});
  if (const auto f = node.find("fixed")) l.fixed = f->boolean();
  if (const auto d = node.find("dimmer")) {
    if (l.fixed) d->fail("a fixed luminaire keeps the start state's dimmer: give one or the other");
    const std::vector<JsonNode> range = d->elements();
    if (range.size() != 2) d->fail("expected [lo, hi]");
    l.dimmer_lo = range[0].number_at_least(0);
    l.dimmer_hi = range[1].number_at_least(0);
    if (l.dimmer_lo > l.dimmer_hi)
      range[0].fail("is above hi (" + std::to_string(l.dimmer_hi) + ")");
  }
  if (const auto c = node.find("aim_cone_deg")) {
    if (l.fixed) c->fail("a fixed luminaire keeps the start state's aim: give one or the other");
    l.aim_cone_deg = c->number_at_least(0);
    if (l.aim_cone_deg > 90) c->fail("must be at most 90 (a half-angle in degrees)");
  }
}

}  // namespace

const char* target_key(TargetKind kind) {
  switch (kind) {
    case TargetKind::kEmMin:
      return "em_min";
    case TargetKind::kEmMax:
      return "em_max";
    case TargetKind::kU0Min:
      return "u0_min";
    case TargetKind::kEMin:
      return "e_min";
    case TargetKind::kEMax:
      return "e_max";
  }
  return "?";
}

DesignTargets parse_design_targets(const nlohmann::json& document, const Scene& scene,
                                   const std::string& where) {
  return parse_design_targets(JsonNode(document, where, "/"), scene);
}

DesignTargets parse_design_targets(const JsonNode& root, const Scene& scene) {
  if (!root.is_object()) root.fail("expected an object with \"sensors\" targets");
  root.expect_keys({"sensors", "luminaires", "objective", "power_w"});
  DesignTargets out;
  out.luminaires.resize(scene.luminaires.size());
  if (const auto sets = root.find("sensors")) {
    if (!sets->is_object()) sets->fail("expected an object mapping sensor set names to targets");
    // Scene order, whatever the document's.
    std::vector<std::optional<JsonNode>> by_set(scene.sensors.size());
    for (const auto& [name, unused] : sets->value().items()) {
      const JsonNode node = sets->at(name);
      if (!node.is_object()) node.fail("expected an object of targets (em_min, u0_min, ...)");
      by_set[set_index(scene, node, name)] = node;
    }
    for (std::size_t s = 0; s < by_set.size(); ++s) {
      if (by_set[s]) read_set_targets(*by_set[s], s, out);
    }
  }
  if (out.targets.empty()) {
    root.fail(
        "no target: give at least one of em_min, em_max, u0_min, e_min, e_max under "
        "\"sensors\": { \"SET NAME\": { ... } }");
  }
  if (const auto lums = root.find("luminaires")) {
    if (!lums->is_object()) lums->fail("expected an object mapping luminaire names to settings");
    for (const auto& [name, unused] : lums->value().items()) {
      const JsonNode node = lums->at(name);
      if (!node.is_object()) node.fail("expected an object (dimmer, aim_cone_deg, fixed)");
      read_freedom(node, out.luminaires[luminaire_index(scene, node, name)]);
    }
  }
  if (const auto o = root.find("objective")) {
    const std::string name = o->string();
    if (name == "power") {
      out.objective = DesignObjective::kPower;
    } else if (name == "uniformity") {
      out.objective = DesignObjective::kUniformity;
    } else {
      o->fail("expected \"power\" or \"uniformity\", got \"" + name + "\"");
    }
  }
  if (out.objective == DesignObjective::kUniformity) {
    const bool level = std::any_of(out.targets.begin(), out.targets.end(), [](const Target& t) {
      return (t.kind == TargetKind::kEmMin || t.kind == TargetKind::kEMin) && t.value > 0;
    });
    if (!level) {
      root.at("objective")
          .fail(
              "\"uniformity\" needs a level to hold: U0 does not change when every dimmer is "
              "scaled, "
              "so give a set an em_min or e_min above 0");
    }
  }
  if (const auto p = root.find("power_w")) {
    if (!p->is_object()) p->fail("expected an object mapping luminaire names to watts");
    for (const auto& [name, unused] : p->value().items()) {
      const JsonNode node = p->at(name);
      out.luminaires[luminaire_index(scene, node, name)].power_w = node.number_at_least(0);
    }
  }
  return out;
}

DesignTargets load_design_targets(const std::filesystem::path& file, const Scene& scene) {
  return parse_design_targets(read_json_file(file), scene, file.string());
}

std::string target_name(const Scene& scene, const Target& target) {
  return scene.sensors.at(target.set).name + ": " + target_key(target.kind);
}

}  // namespace relight
