// What render, probe, bench and the demo share: open a .rlt, apply lighting states,
// relight, and hand out per-receiver irradiance or rendered images.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "render/vertex_shading.h"
#include "runtime/relighter.h"
#include "runtime/transfer_file.h"

namespace relight {

struct RelitScene {
  std::unique_ptr<TransferFile> transfer;  // stable address: the Relighter refers to it
  std::unique_ptr<Relighter> relighter;
  std::unique_ptr<RayTracer> tracer;          // opaque triangles, built on first render
  std::unique_ptr<RayTracer> portal_tracer;   // portal triangles (ids: portal index)
  std::vector<float> irradiance;      // 3 per receiver: vertices, then sensors

  // Applies a state and relights.
  void apply(const LightingState& state);
  // Sensor illuminance in scene order.
  std::vector<Rgb> sensor_irradiance() const;
  // Per-vertex radiance seen through a camera (Gouraud-equivalent); with
  // `pixel_direct`, direct light is evaluated exactly at each pixel's surface point and
  // only the interreflected light is interpolated between vertices.
  ShadedImages render(const Camera& camera, int width, int height, bool pixel_direct = false);
};

RelitScene relight_transfer_file(const std::filesystem::path& rlt,
                                 const std::optional<std::filesystem::path>& state_file);

}  // namespace relight
