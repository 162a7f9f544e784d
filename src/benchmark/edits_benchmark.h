// `relight bench SCENE.rlt --edits [--frames N]`: every kind of edit the scene allows, each
// `frames` times along a path (benchmark/edit_paths.h), shown as the studio shows it
// (runtime/progressive_frames.h): a first frame, then the converged one when they differ.
// Edits: dimmer, aim, colour_temperature, distribution_swap (when two luminaires differ),
// luminaire_move, sky_time (a sun by place and time a minute a frame, by angles 0.25°), sky_type (a
// CIE sky), environment_rotation (a map), object_dragged, objects_moving, emitter_moved,
// material_albedo, material_roughness. Each starts from the scene's own state.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "benchmark/frame_benchmark.h"

namespace relight {

// One line per edit: {"edit", "first_ms", "converged_ms", "first_error", "frames",
// "receivers"} — medians; first_ms from the state applied to the first frame, complete for
// every receiver; converged_ms to the converged frame; first_error the mean relative difference
// of the first frame's sensor illuminance from the converged frame's (null without sensors) —
// then the summary {"edits", "worst_first_ms", "worst_converged_ms"}.
std::vector<nlohmann::ordered_json> run_edits_bench(const BenchOptions& options);

}  // namespace relight
