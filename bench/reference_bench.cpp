// Foundation benchmarks on the demo room: plain Embree closest-hit and occlusion rays
// (the baseline, cosine-distributed from random surface points) and the reference path
// tracer's sensor estimate, measured in the same run so ratios are meaningful on a
// shared, noisy machine. Run: make bench (or build/relight_benchmarks).
#include <benchmark/benchmark.h>

#include <tbb/parallel_for.h>

#include "cli/demo_room.h"
#include "light/luminaire_frame.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "reference/reference_tracer.h"
#include "scene/scene_loader.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

struct DemoRoom {
  Scene scene = scene_from_json(demo_room_scene(), "demo-room.json");
  PreparedMesh mesh = prepare_mesh(scene.geometry, PreparationSettings{});
  TracedScene traced = build_traced_scene(mesh, scene.materials);
  std::vector<Ray> rays;

  DemoRoom() {
    // Rays leaving random front-facing surface points in cosine directions, as the
    // path tracer and the gather operator shoot them.
    Pcg32 rng(3, 1);
    for (int i = 0; i < 1 << 18; ++i) {
      const auto t = static_cast<std::uint32_t>(rng.next_u32() % mesh.triangles.size());
      double u = rng.next_double(), v = rng.next_double();
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vec3 n = geometric_normal(mesh, t);
      const Vec3 d = frame_from_normal(n).to_world(
          sample_cosine_hemisphere(rng.next_double(), rng.next_double()));
      rays.push_back({offset_from_surface(point_on_triangle(mesh, t, u, v), n), d, 0, 20});
    }
  }
};

const DemoRoom& demo() {
  static const DemoRoom room;
  return room;
}

void BM_EmbreeIntersect(benchmark::State& state) {
  const DemoRoom& room = demo();
  for (auto _ : state) {
    tbb::parallel_for(std::size_t{0}, room.rays.size(), [&](std::size_t i) {
      benchmark::DoNotOptimize(room.traced.opaque.intersect(room.rays[i]));
    });
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(room.rays.size()),
                                                benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EmbreeIntersect)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_EmbreeOccluded(benchmark::State& state) {
  const DemoRoom& room = demo();
  for (auto _ : state) {
    tbb::parallel_for(std::size_t{0}, room.rays.size(), [&](std::size_t i) {
      benchmark::DoNotOptimize(room.traced.opaque.occluded(room.rays[i]));
    });
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(room.rays.size()),
                                                benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EmbreeOccluded)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReferenceWorkPlane(benchmark::State& state) {
  const DemoRoom& room = demo();
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(room.scene);
  const ReferenceScene ref = make_reference_scene(room.scene, room.mesh, room.traced, luminaires);
  ReferenceSettings settings;
  settings.spp = static_cast<int>(state.range(0));
  settings.progress = false;
  ReferenceStats stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(reference_sensor_illuminance(room.scene, ref, settings, &stats));
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(stats.rays),
                                                benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ReferenceWorkPlane)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace relight
