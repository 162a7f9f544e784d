#include "benchmark/layout_benchmark.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "benchmark/bench_timing.h"
#include "common/input_error.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

double since_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

nlohmann::json bench_layout(const BenchOptions& args) {
  RelitScene relit(args.rlt, std::nullopt);
  if (relit.scene().luminaires.empty()) {
    fail_input(args.rlt, "--layout needs a scene with luminaires");
  }
  Relighter& relighter = relit.relighter();
  std::vector<float> irradiance(3 * relighter.receivers());
  LightingState state = relighter.state();
  const Bounds bounds = relit.scene().bounds();
  const Vec3 home = state.luminaires.front().position;
  // Along the longer horizontal axis, toward the side with room for 0.4 m.
  const Vec3 extent = bounds.max - bounds.min;
  Vec3 step = extent.x >= extent.z ? Vec3{0.2, 0, 0} : Vec3{0, 0, 0.2};
  if (!contains(bounds, home + step * 2.0)) step = step * -1.0;
  LuminaireState added = state.luminaires.front();
  added.name = "bench added luminaire";
  const Vec3 middle = (bounds.min + bounds.max) * 0.5;
  added.position = home + (Vec3{middle.x, home.y, middle.z} - home) * 0.5;

  relighter.relight(irradiance);  // warm
  std::vector<double> first_ms, converged_ms, trace_ms, bounce_ms;
  for (int i = 0; i < args.frames; ++i) {
    if (i == 0) state.luminaires.push_back(added);
    state.luminaires.front().position = home + step * (1.0 + i % 2);
    const auto start = std::chrono::steady_clock::now();
    relighter.set_layout_bounce(false);
    relighter.set_state(state);
    relighter.relight(irradiance);
    first_ms.push_back(since_ms(start));
    trace_ms.push_back(relighter.luminaires().last_trace_seconds() * 1e3);
    relighter.set_layout_bounce(true);
    relighter.relight(irradiance);
    converged_ms.push_back(since_ms(start));
    bounce_ms.push_back(relighter.luminaires().last_bounce_seconds() * 1e3);
  }
  return {{"mode", "layout"},
          {"receivers", relighter.receivers()},
          {"luminaires", state.luminaires.size()},
          {"luminaires_live", relighter.luminaires().live_count()},
          {"frames", args.frames},
          {"first_frame_ms", median(first_ms)},
          {"converged_ms", median(converged_ms)},
          {"trace_ms", median(trace_ms)},
          {"bounce_ms", median(bounce_ms)}};
}

}  // namespace relight
