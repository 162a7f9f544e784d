// The scene a lighting state's layout makes (the studio's "Export scene"): the precomputed
// scene's JSON with its luminaires replaced by the state's — each where the state hangs it, with
// its aim, C0, colour, dimmer, size and distribution, the luminaires the state adds after them,
// those it switches off left out — so that a precompute of the exported file stores the layout
// as ordinary luminaires. Every relative "file" path is made absolute against the scene's
// folder, so that the exported file can be saved anywhere. Pinned by
// tests/runtime/scene_export_test.cpp.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "light/lighting_state.h"

namespace relight {

// `scene_json` is the scene document as precomputed (its "file" paths relative to the folder
// of `scene_file`); `state` is of that scene.
nlohmann::json scene_json_with_layout(const nlohmann::json& scene_json,
                                      const std::filesystem::path& scene_file,
                                      const LightingState& state);

// A distribution as the scene format writes it (docs/scene-format.md).
nlohmann::json distribution_json(const DistributionSpec& spec);

}  // namespace relight
