// A scene document precomputed in this process into DIR/NAME.rlt (with DIR/NAME.json beside
// it, as `relight precompute` would leave them), for tests and benchmarks that open a .rlt.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "support/temp_dir.h"

namespace relight::testing {

inline std::filesystem::path write_precomputed(const TempDir& dir, const std::string& name,
                                               const nlohmann::json& document) {
  const std::filesystem::path scene_file = dir.write(name + ".json", document.dump());
  const std::filesystem::path rlt = dir.path() / (name + ".rlt");
  const Scene scene = scene_from_json(document, scene_file);
  PrecomputeOptions options;
  options.progress = false;
  write_transfer_file(rlt, precompute_transfer(scene, options), scene, document, scene_file);
  return rlt;
}

}  // namespace relight::testing
