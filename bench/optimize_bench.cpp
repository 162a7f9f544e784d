// `relight optimize` speed: an open-plan office of 20 × 10 m with 50 downlights on a
// 2 m grid and a work plane of 50 × 40 = 2,000 sensors, dimmers only, power objective with an
// Em and a U0 target (the issue's bound: 1 s on 2 cores). Measured against a baseline in the
// same run: one relight of the whole scene (every luminaire's transfer summed once), which
// the model needs 51 of. The scene is precomputed once at low settings (half a minute).
#include <benchmark/benchmark.h>

#include <memory>

#include "design/optimize.h"
#include "support/precomputed_file.h"

namespace relight {
namespace {

nlohmann::json open_plan_office() {
  nlohmann::json doc = nlohmann::json::parse(R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] }, "floor": { "albedo": [0.25, 0.2, 0.15] } },
    "geometry": [
      { "type": "box", "min": [0, 0, 0], "max": [20, 3, 10], "normals": "inward", "material": "grey" },
      { "type": "quad", "corner": [0, 0.001, 0], "u": [0, 0, 10], "v": [20, 0, 0], "material": "floor" } ],
    "sensors": [ { "name": "work plane", "grid": { "corner": [0.2, 0.8, 0.2], "u": [19.6, 0, 0],
                   "v": [0, 0, 9.6], "nu": 50, "nv": 40 } } ],
    "precompute": { "max_edge": 1.0, "gather_rays": 16, "sensor_gather_rays": 32, "sh_order": 6 }
  })");
  nlohmann::json luminaires = nlohmann::json::array();
  for (int i = 0; i < 10; ++i) {
    for (int k = 0; k < 5; ++k) {
      const double exponent = 1 + (i + k) % 4;  // four beam widths, so the columns differ
      luminaires.push_back(
          {{"name",
            std::string(1, 'L').append(std::to_string(i)).append("-").append(std::to_string(k))},
           {"position", {1 + 2 * i, 2.9, 1 + 2 * k}},
           {"distribution",
            {{"type", "cosine_power"}, {"candela", 400 + 50 * k}, {"exponent", exponent}}}});
    }
  }
  doc["luminaires"] = luminaires;
  return doc;
}

struct Office {
  testing::TempDir dir;
  std::filesystem::path rlt = testing::write_precomputed(dir, "office", open_plan_office());
};

// Precomputed once (half a minute), kept for every benchmark.
const Office& office() {
  static const std::unique_ptr<Office> made = std::make_unique<Office>();
  return *made;
}

// Baseline: one relight of the whole scene after a dimmer changed.
void BM_OptimizeBaselineOneRelight(benchmark::State& state) {
  RelitScene relit(office().rlt, std::nullopt);
  LightingState s = relit.state();
  int k = 0;
  for (auto _ : state) {
    s.luminaires[0].dimmer = (++k % 2) ? 0.5 : 1.0;
    relit.apply(s);
    benchmark::DoNotOptimize(relit.irradiance().data());
  }
}
BENCHMARK(BM_OptimizeBaselineOneRelight)->Unit(benchmark::kMillisecond)->UseRealTime();

void optimize_office(benchmark::State& state, const char* objective) {
  RelitScene relit(office().rlt, std::nullopt);
  const DesignTargets targets = parse_design_targets(
      nlohmann::json{{"sensors", {{"work plane", {{"em_min", 150}, {"u0_min", 0.5}}}}},
                     {"objective", objective}},
      relit.scene(), "targets");
  OptimizeResult r;
  for (auto _ : state) r = optimize_lighting(relit, {}, targets, {});
  state.counters["feasible"] = r.feasible ? 1 : 0;
  state.counters["iterations"] = r.iterations;
  state.counters["power"] = r.power_w;
  state.counters["U0"] = r.targets.back().achieved;
}

// 50 luminaires × 2,000 sensors, dimmers only: the model (51 relights) and the program.
void BM_Optimize50Luminaires2000SensorsPower(benchmark::State& state) {
  optimize_office(state, "power");
}
BENCHMARK(BM_Optimize50Luminaires2000SensorsPower)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same with U0 maximised (a bisection: about 17 programs).
void BM_Optimize50Luminaires2000SensorsUniformity(benchmark::State& state) {
  optimize_office(state, "uniformity");
}
BENCHMARK(BM_Optimize50Luminaires2000SensorsUniformity)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace relight
