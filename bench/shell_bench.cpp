// Portal shell benchmarks (sources/portals/shell.h), at the transfer's default N = 32, SH l < 6,
// per state change: a CIE clear sky alone (the environment cubemap + SH projection dominate), with
// frosted glass of several widths (the frost plan reused between frames, as a run time keeps
// it while the glass does not change; the plan alone is timed too), and with moving exterior
// buildings (BVH rebuilt and 3×3 sub-rays per texel every frame).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "light/environment.h"
#include "light/sky_model.h"
#include "math/cubemap.h"
#include "sources/portals/shell.h"
#include "sources/portals/shell_frost.h"

namespace relight {
namespace {

constexpr int kFace = 32, kOrder = 6;
const PortalFrame kPortal{{0, 1.5, 0}, {1, 0, 0}};

Environment sky_at(int frame) {
  const double az = radians(60.0 + (frame % 60)), h = radians(30.0);
  const Vec3 sun{std::cos(h) * std::sin(az), std::sin(h), -std::cos(h) * std::cos(az)};
  return make_sky_environment(make_sky_from_horizontal_illuminance(12, sun, 15000, 0.2, 80000));
}

// n axis-aligned boxes 10–30 m east of the window, shifted along z by `shift`.
std::vector<ExteriorObject> buildings(int n, double shift) {
  std::vector<ExteriorObject> out;
  for (int b = 0; b < n; ++b) {
    const Vec3 lo{10.0 + 4 * b, -2, -30.0 + 12 * b + shift}, hi = lo + Vec3{8, 6.0 + 3 * b, 8};
    ExteriorObject o;
    for (int c = 0; c < 8; ++c)
      o.positions.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    o.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    o.albedo = {0.35, 0.3, 0.25};
    out.push_back(std::move(o));
  }
  return out;
}

void run_shell(benchmark::State& state, double frost_deg, int building_count) {
  Shell shell;
  ShellWorkspace workspace;
  int frame = 0;
  for (auto _ : state) {
    const Environment env = sky_at(frame);
    const std::vector<ExteriorObject> exterior = buildings(building_count, 0.1 * (frame % 50));
    ShellInputs in;
    in.environment = &env;
    in.frost_deg = frost_deg;
    in.exterior = exterior;
    render_shell(in, kPortal, kFace, kOrder, shell, workspace);
    benchmark::DoNotOptimize(shell.sh.data());
    ++frame;
  }
}

void BM_ShellClearSky(benchmark::State& state) {
  run_shell(state, 0, 0);
}
BENCHMARK(BM_ShellClearSky)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShellClearSkyFrost(benchmark::State& state) {
  run_shell(state, static_cast<double>(state.range(0)), 0);
}
BENCHMARK(BM_ShellClearSkyFrost)
    ->Arg(2)
    ->Arg(5)
    ->Arg(15)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ShellClearSkyBuildings(benchmark::State& state) {
  run_shell(state, 0, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_ShellClearSkyBuildings)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShellClearSkyBuildingsFrost5(benchmark::State& state) {
  run_shell(state, 5, 5);
}
BENCHMARK(BM_ShellClearSkyBuildingsFrost5)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FrostPlan(benchmark::State& state) {
  FrostPlan plan;
  for (auto _ : state) {
    plan.face_size = 0;  // force a rebuild
    make_frost_plan(kFace, kPortal.outward, static_cast<double>(state.range(0)), plan);
    benchmark::DoNotOptimize(plan.inv_z.data());
  }
  state.counters["front_texels"] = static_cast<double>(plan.texel.size());
}
BENCHMARK(BM_FrostPlan)
    ->Arg(2)
    ->Arg(5)
    ->Arg(15)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FrostApply(benchmark::State& state) {
  FrostPlan plan;
  make_frost_plan(kFace, kPortal.outward, static_cast<double>(state.range(0)), plan);
  const std::vector<Rgb> sky = environment_cubemap(sky_at(0), kFace);
  std::vector<Rgb> cubemap, scratch;
  for (auto _ : state) {
    cubemap = sky;
    apply_frost(plan, cubemap, scratch);
    benchmark::DoNotOptimize(cubemap.data());
  }
}
BENCHMARK(BM_FrostApply)
    ->Arg(2)
    ->Arg(5)
    ->Arg(15)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace relight
