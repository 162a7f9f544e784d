// The small scene the state, targets and studio-message fuzz targets apply their input to: a box
// room with a luminaire, a window, an emitter, a movable object (every kind a state can name)
// and a sensor set "desk" (what design targets name).
#pragma once

#include "scene/json_node.h"
#include "scene/scene_loader.h"

namespace relight::fuzz {

inline const Scene& fuzz_room() {
  static const Scene s = scene_from_json(parse_json_text(R"({
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
                   "max": [1.5, 0.5, 1.5], "material": "grey" } ] } ],
    "sensors": [ { "name": "desk", "points": [[1, 0.8, 1], [2, 0.8, 2]], "normal": [0, 1, 0] } ]
  })",
                                                         "scene.json"),
                                         "/nonexistent/scene.json");
  return s;
}

}  // namespace relight::fuzz
