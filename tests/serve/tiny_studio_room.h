// A tiny precomputed room for the studio's tests: a grey box with a south window (a portal to
// a uniform sky), a downlight with a curve distribution and a work-plane grid, precomputed at
// low settings into a .rlt in a temporary folder (about a second); optionally with a near-field
// emitter or a movable object.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "support/temp_dir.h"

namespace relight::testing {

inline nlohmann::json tiny_studio_room_json() {
  return nlohmann::json::parse(R"({
  "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] }, "floor": { "albedo": [0.3, 0.2, 0.1] },
                 "glass": { "albedo": [0, 0, 0], "portal": true } },
  "geometry": [
    { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward", "material": "grey" },
    { "type": "quad", "corner": [0, 0.001, 0], "u": [0, 0, 3], "v": [3, 0, 0], "material": "floor" },
    { "type": "quad", "corner": [1, 0.8, 2.999], "u": [1, 0, 0], "v": [0, 1, 0], "material": "glass" } ],
  "portals": [ { "name": "south", "material": "glass",
                 "environment": { "type": "uniform", "luminance": 1000 } } ],
  "luminaires": [ { "name": "down", "position": [1.5, 2.4, 1.5],
      "distribution": { "type": "curve", "gamma_deg": [0, 30, 60, 90],
                        "candela": [500, 400, 100, 0] } } ],
  "sensors": [ { "name": "floor", "grid": { "corner": [0.5, 0.8, 0.5], "u": [2, 0, 0],
                                            "v": [0, 0, 2], "nu": 3, "nv": 2 } } ],
  "cameras": [ { "name": "in", "eye": [1.5, 1.5, 0.2], "target": [1.5, 1, 3] } ],
  "precompute": { "max_edge": 0.75, "gather_rays": 16, "sensor_gather_rays": 64, "sh_order": 4,
                  "portal_face_size": 8, "portal_sh_order": 3 }
})");
}

// The room with a downward-facing 0.4 × 0.4 m quad emitter "panel" under the ceiling
// (corner [1, 2, 1]: pivot [1.2, 2, 1.2]).
inline nlohmann::json tiny_studio_room_with_emitter_json() {
  nlohmann::json document = tiny_studio_room_json();
  document["emitters"] = nlohmann::json::parse(R"([ { "name": "panel",
      "geometry": { "type": "quad", "corner": [1, 2, 1], "u": [0.4, 0, 0], "v": [0, 0, 0.4] },
      "luminance": 2000, "color": [1, 0.5, 0.25] } ])");
  document["precompute"]["nearfield_directions"] = 16;
  return document;
}

// The room with a movable object "cabinet": one box 0.5 × 1.2 × 0.4 m standing on the floor
// beside the downlight (pivot [0.75, 0.6, 0.7]), of material "grey".
inline constexpr double kCabinetMin[3] = {0.5, 0, 0.5}, kCabinetMax[3] = {1.0, 1.2, 0.9};
inline nlohmann::json tiny_studio_room_with_object_json() {
  nlohmann::json document = tiny_studio_room_json();
  document["objects"] = nlohmann::json::array(
      {{{"name", "cabinet"},
        {"geometry",
         nlohmann::json::array({{{"type", "box"},
                                 {"min", {kCabinetMin[0], kCabinetMin[1], kCabinetMin[2]}},
                                 {"max", {kCabinetMax[0], kCabinetMax[1], kCabinetMax[2]}},
                                 {"material", "grey"}}})}}});
  return document;
}

struct TinyStudioRoom {
  TempDir dir;
  std::filesystem::path rlt = dir.path() / "tiny.rlt";
  TransferFile transfer;

  explicit TinyStudioRoom(const nlohmann::json& document = tiny_studio_room_json())
      : transfer(make(document)) {}

 private:
  TransferFile make(const nlohmann::json& document) {
    const std::filesystem::path scene_file = dir.write("tiny.json", document.dump());
    const Scene scene = scene_from_json(document, scene_file);
    PrecomputeOptions options;
    options.progress = false;
    write_transfer_file(rlt, precompute_transfer(scene, options), scene, document, scene_file);
    return open_transfer_file(rlt);
  }
};

}  // namespace relight::testing
