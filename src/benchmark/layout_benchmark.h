// `relight bench SCENE.rlt --layout`: a designer laying out luminaires. The first frame adds a
// luminaire (the first one's photometry, halfway from it toward the middle of the scene) and
// every frame moves the first luminaire 20 cm along the room's longer horizontal axis (0.2 m and
// 0.4 m from where the precompute hung it, in turn, so that it is always away from its stored
// transfer). Each frame is timed twice (sources/luminaires/luminaire_lighting.h): the first
// frame the studio shows (the moved and added luminaires' direct light traced at every receiver,
// their interreflection the nearest stored response) and the converged one (their own light
// bounced through the gather operator). Prints first_frame_ms, converged_ms (from the state
// applied to the converged sum), trace_ms, bounce_ms, receivers and luminaires_live (medians).
#pragma once

#include <nlohmann/json.hpp>

#include "benchmark/frame_benchmark.h"

namespace relight {

// InputError for a scene without luminaires.
nlohmann::json bench_layout(const BenchOptions& options);

}  // namespace relight
