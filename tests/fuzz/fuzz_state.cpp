// Fuzz target (issue 16): a lighting state document (docs/lighting-state.md) applied to a small
// scene with a luminaire, a window, an emitter and a movable object, as `relight probe --state`
// and the studio read it (runtime/lighting_state.h). Bad input must end in InputError; anything
// else is a defect.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.h"
#include "runtime/lighting_state.h"
#include "scene/json_node.h"
#include "scene/scene_loader.h"

namespace {

const relight::Scene& scene() {
  static const relight::Scene s = relight::scene_from_json(relight::parse_json_text(R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] },
                   "glass": { "albedo": [0.9, 0.9, 0.9], "portal": true } },
    "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [4, 3, 4], "normals": "inward",
                    "material": "grey" },
                  { "type": "quad", "corner": [1, 1, 3.99], "u": [1, 0, 0], "v": [0, 1, 0],
                    "material": "glass" } ],
    "portals": [ { "name": "window", "material": "glass",
                   "environment": { "type": "uniform", "luminance": 1000 } } ],
    "luminaires": [ { "name": "down", "position": [2, 2.9, 2],
        "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } } ],
    "emitters": [ { "name": "panel", "geometry": { "type": "quad", "corner": [1, 2.5, 1],
        "u": [0.5, 0, 0], "v": [0, 0, 0.5] }, "luminance": 500 } ],
    "objects": [ { "name": "box", "geometry": [ { "type": "box", "min": [1, 0, 1],
                   "max": [1.5, 0.5, 1.5], "material": "grey" } ] } ]
  })",
                                                                                    "scene.json"),
                                                           "/nonexistent/scene.json");
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    relight::LightingState state = relight::default_lighting_state(scene());
    relight::apply_lighting_state(state, scene(), relight::parse_json_text(text, "state.json"),
                                  "state.json", "/nonexistent");
  } catch (const relight::InputError&) {
  }
  return 0;
}
