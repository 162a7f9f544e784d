// What render, probe and bench share: open a .rlt, apply an optional lighting state,
// relight, and hand out per-receiver irradiance.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "runtime/relighter.h"
#include "runtime/transfer_file.h"

namespace relight {

struct RelitScene {
  std::unique_ptr<TransferFile> transfer;  // stable address: the Relighter refers to it
  std::unique_ptr<Relighter> relighter;
  std::vector<float> irradiance;  // 3 per receiver: vertices, then sensors

  // Sensor illuminance in scene order.
  std::vector<Rgb> sensor_irradiance() const;
};

RelitScene relight_transfer_file(const std::filesystem::path& rlt,
                                 const std::optional<std::filesystem::path>& state_file);

}  // namespace relight
