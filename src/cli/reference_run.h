// What `relight reference` does, reusable by `relight demo`: load photometry, prepare
// and trace the scene, estimate sensors and/or render an image, write the outputs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/image_io.h"
#include "scene/scene.h"

namespace relight {

// One image file written from a rendering: .png (tone-mapped or false colour) or .exr.
struct ImageOutput {
  std::filesystem::path file;
  DisplayOptions display;
};

struct ReferenceRequest {
  int spp = 64;
  std::uint64_t seed = 1;
  int max_bounces = 0;  // ReferenceSettings::max_bounces
  std::optional<std::filesystem::path> sensors_out;
  bool sensors = true;                // estimate sensors (and print statistics)
  std::optional<std::string> camera;  // scene camera name; first camera when absent
  int width = 640, height = 480;
  std::vector<ImageOutput> images;  // all written from one rendering
  bool progress = true;
  // A lighting state (docs/lighting-state.md) applied to the scene: luminaires, windows'
  // environment, tint, frost and exterior objects, emitters. Absent: the scene's own.
  std::optional<std::filesystem::path> state;
};

void run_reference(const Scene& scene, const ReferenceRequest& request);

}  // namespace relight
