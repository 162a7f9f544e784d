// `relight annual` speed: the demo room's 414 work-plane sensors through the
// occupied hours (08:00–18:00) of a synthetic year with the sun up (tests/support/
// synthetic_epw.h, 48.14° N: 3,470 hours) and through all its hours (4,399 with the sun up),
// against a baseline measured in the same run: one
// hour relit as `relight probe --state` relights it (every receiver, the sun's patch bounced
// through the room). The bound is 8,760 hours in 10 s on 2 cores. The room is
// precomputed once (a minute).
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

#include "cli/demo_room.h"
#include "light/epw_weather.h"
#include "runtime/annual_daylight.h"
#include "support/precomputed_file.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

struct DemoYear {
  testing::TempDir dir;
  std::filesystem::path rlt = testing::write_precomputed(dir, "demo-room", demo_room_scene());
  WeatherFile weather = parse_epw(testing::synthetic_epw(), "year.epw");
  AnnualHours hours = annual_hours(weather, {}, 0);                 // 08:00–18:00
  AnnualHours every_hour = annual_hours(weather, {0, 24 * 60}, 0);  // the 8,760 hours
};

// Precomputed once (a minute), kept for both benchmarks.
const DemoYear& demo_year() {
  static const std::unique_ptr<DemoYear> made = std::make_unique<DemoYear>();
  return *made;
}

// Baseline: hours relit one by one as probe relights one (a fresh sun bounce each).
void BM_AnnualBaselineProbeHours(benchmark::State& state) {
  const DemoYear& y = demo_year();
  RelitScene relit(y.rlt, std::nullopt);
  LightingState s = daylight_alone(relit.state());
  std::size_t h = 0;
  for (auto _ : state) {
    for (PortalState& p : s.portals) p.environment = y.hours.hours[h].sky;
    h = (h + 97) % y.hours.hours.size();  // hours spread over the year
    relit.apply(s);
    benchmark::DoNotOptimize(relit.irradiance().data());
  }
}
BENCHMARK(BM_AnnualBaselineProbeHours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(40);

// The year: the sensors' importance solved once (opening), then every sunlit hour of `hours`.
void annual_year(benchmark::State& state, const AnnualHours& hours) {
  const DemoYear& y = demo_year();
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::unique_ptr<RelitScene> relit = open_for_annual(y.rlt);
    const double open_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const AnnualDaylight year = annual_daylight(*relit, daylight_alone(relit->state()), hours.hours,
                                                every_sensor_set(relit->scene()));
    state.counters["hours"] = static_cast<double>(hours.hours.size());
    state.counters["importance_s"] = open_s;
    state.counters["sweep_s"] = year.values.total_seconds;
    state.counters["streams"] = static_cast<double>(year.values.streams);
    state.counters["shells_thread_s"] = year.values.shell_seconds;
    state.counters["hours_thread_s"] = year.values.hour_seconds;
    state.counters["ms_per_hour"] =
        1e3 * year.values.total_seconds / static_cast<double>(hours.hours.size());
  }
}

void BM_AnnualDemoRoomOccupiedYear(benchmark::State& state) {
  annual_year(state, demo_year().hours);
}
BENCHMARK(BM_AnnualDemoRoomOccupiedYear)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// The bound: all 8,760 hours of the year (4,399 with the sun up) in 10 s on 2 cores.
void BM_AnnualDemoRoomEveryHour(benchmark::State& state) {
  annual_year(state, demo_year().every_hour);
}
BENCHMARK(BM_AnnualDemoRoomEveryHour)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace relight
