// What `relight precompute` does, reusable by `relight demo`.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "sources/precompute.h"

namespace relight {

// Precomputes the scene `document` (read from `scene_file`), writes `output` and
// prints the summary: rays, Mrays/s and time per phase, bounces, bytes stored.
void run_precompute(const nlohmann::json& document, const std::filesystem::path& scene_file,
                    const std::filesystem::path& output, const PrecomputeOptions& options);

}  // namespace relight
