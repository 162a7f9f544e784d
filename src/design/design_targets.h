// What the designer asks of inverse lighting design (`relight optimize`; the future work Dobashi et
// al. 1995 name in their conclusion): targets per sensor set, what each luminaire may do, and what
// to optimise. The TARGETS.json contract (docs/optimize.md):
//   { "sensors": { "SET": { "em_min", "em_max", "u0_min", "e_min", "e_max" } },
//     "luminaires": { "NAME": { "dimmer": [lo, hi], "aim_cone_deg": deg, "fixed": true } },
//     "objective": "power" | "uniformity", "power_w": { "NAME": watts } }
// Every key is optional but at least one target must be given. Em is a set's mean illuminance,
// E a single point's, U0 = Emin / Em (EN 12464-1), all in lux of the sensors' readings (the Y of
// their RGB, as `relight probe` prints them). Luminaires not named are free dimmers in 0..1.
// Bad targets — an unknown set or luminaire, a min above its max, a value out of range — are
// InputErrors naming the JSON path (exit 2). Tests: tests/design/design_targets_test.cpp.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/json_node.h"
#include "scene/scene.h"

namespace relight {

// The kinds of target, in the order a set's targets are listed and reported.
enum class TargetKind { kEmMin, kEmMax, kU0Min, kEMin, kEMax };
inline constexpr TargetKind kTargetKinds[] = {TargetKind::kEmMin, TargetKind::kEmMax,
                                              TargetKind::kU0Min, TargetKind::kEMin,
                                              TargetKind::kEMax};
// The TARGETS.json key of a kind ("em_min", ...).
const char* target_key(TargetKind kind);
// Whether the kind is a lower bound (the achieved value must be at least the target's).
constexpr bool is_lower_bound(TargetKind kind) {
  return kind == TargetKind::kEmMin || kind == TargetKind::kU0Min || kind == TargetKind::kEMin;
}

struct Target {
  std::size_t set = 0;  // index into scene.sensors
  TargetKind kind = TargetKind::kEmMin;
  double value = 0;  // lx, or the ratio for U0
};

struct LuminaireFreedom {
  bool fixed = false;  // keeps the start state's setting: not a variable
  double dimmer_lo = 0, dimmer_hi = 1;
  double aim_cone_deg = 0;        // > 0: the aim may turn this far from the scene's aim
  std::optional<double> power_w;  // the "power_w" key, W at dimmer 1
};

enum class DesignObjective { kPower, kUniformity };

struct DesignTargets {
  std::vector<Target> targets;               // sets in scene order, kinds in kTargetKinds order
  std::vector<LuminaireFreedom> luminaires;  // scene order
  DesignObjective objective = DesignObjective::kPower;
};

// `where` names the document in messages (a file).
DesignTargets parse_design_targets(const nlohmann::json& document, const Scene& scene,
                                   const std::string& where);
// The same from a node of a larger document (the studio's "optimize" message).
DesignTargets parse_design_targets(const JsonNode& root, const Scene& scene);
DesignTargets load_design_targets(const std::filesystem::path& file, const Scene& scene);

// "SET: em_min", how a target is named in what `relight optimize` prints.
std::string target_name(const Scene& scene, const Target& target);

}  // namespace relight
