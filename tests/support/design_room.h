// A small precomputed office for the inverse-design tests: a 6 × 3 × 4 m grey room (walls of quads,
// the south one around a 1.5 × 1.2 m window) with three downlights under the ceiling ("left" and
// "right" cosine-power, "middle" the bilateral IES file of tests/data/photometry with its 25 W
// input power, 0.2 m lower so that its spherical luminous opening of 1 ft stays below the ceiling),
// a "desk" work-plane grid of 6 × 4 points and a "wall" grid of 4 × 2 points facing into the room
// from the east wall, and a south window (a portal to a uniform sky of 2000 cd/m²); precomputed at
// low settings into a .rlt in a temporary folder (a few seconds).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "support/precomputed_file.h"

namespace relight::testing {

inline nlohmann::json design_room_json() {
  nlohmann::json document = nlohmann::json::parse(R"({
  "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] }, "floor": { "albedo": [0.3, 0.25, 0.2] },
                 "glass": { "albedo": [0, 0, 0], "portal": true } },
  "geometry": [
    { "type": "quad", "corner": [0, 0, 0], "u": [0, 0, 4], "v": [6, 0, 0], "material": "floor" },
    { "type": "quad", "corner": [0, 3, 0], "u": [6, 0, 0], "v": [0, 0, 4], "material": "grey" },
    { "type": "quad", "corner": [0, 0, 0], "u": [0, 3, 0], "v": [0, 0, 4], "material": "grey" },
    { "type": "quad", "corner": [6, 0, 0], "u": [0, 0, 4], "v": [0, 3, 0], "material": "grey" },
    { "type": "quad", "corner": [0, 0, 0], "u": [6, 0, 0], "v": [0, 3, 0], "material": "grey" },
    { "type": "quad", "corner": [0, 0, 4], "u": [0, 3, 0], "v": [2, 0, 0], "material": "grey" },
    { "type": "quad", "corner": [3.5, 0, 4], "u": [0, 3, 0], "v": [2.5, 0, 0], "material": "grey" },
    { "type": "quad", "corner": [2, 0, 4], "u": [0, 1, 0], "v": [1.5, 0, 0], "material": "grey" },
    { "type": "quad", "corner": [2, 2.2, 4], "u": [0, 0.8, 0], "v": [1.5, 0, 0], "material": "grey" },
    { "type": "quad", "corner": [2, 1, 4], "u": [1.5, 0, 0], "v": [0, 1.2, 0], "material": "glass" } ],
  "portals": [ { "name": "south", "material": "glass",
                 "environment": { "type": "uniform", "luminance": 2000 } } ],
  "luminaires": [
    { "name": "left", "position": [1.5, 2.9, 1.5],
      "distribution": { "type": "cosine_power", "candela": 600, "exponent": 2 } },
    { "name": "middle", "position": [3, 2.8, 2.5],
      "distribution": { "type": "ies", "file": "IES_FILE" } },
    { "name": "right", "position": [4.5, 2.9, 1.5],
      "distribution": { "type": "cosine_power", "candela": 900, "exponent": 3 } } ],
  "sensors": [
    { "name": "desk", "grid": { "corner": [0.5, 0.8, 0.5], "u": [5, 0, 0], "v": [0, 0, 3],
                                "nu": 6, "nv": 4 } },
    { "name": "wall", "grid": { "corner": [5.99, 1.0, 0.5], "u": [0, 0, 3], "v": [0, 1, 0],
                                "nu": 4, "nv": 2 }, "normal": [-1, 0, 0] } ],
  "cameras": [ { "name": "in", "eye": [3, 1.6, 0.2], "target": [3, 1, 4] } ],
  "precompute": { "max_edge": 0.75, "gather_rays": 16, "sensor_gather_rays": 64, "sh_order": 6,
                  "portal_face_size": 8, "portal_sh_order": 3 }
})");
  document["luminaires"][1]["distribution"]["file"] =
      std::string(RELIGHT_TEST_DATA) + "/photometry/bilateral_90_270_2019.ies";
  return document;
}

struct DesignRoom {
  TempDir dir;
  std::filesystem::path rlt;

  explicit DesignRoom(const nlohmann::json& document = design_room_json())
      : rlt(write_precomputed(dir, "office", document)) {}
};

}  // namespace relight::testing
