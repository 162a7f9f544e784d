// Luminaire relighting benchmarks on the demo room, each beside the baseline it is
// judged against, measured in the same run:
//  - the run-time weighted sum (a frame) against a plain parallel streaming read of the
//    same number of bytes (bytes_per_second of both: the ratio is the figure);
//  - re-aiming a luminaire (SH projection, rotation and exact direct field) + a frame;
//  - the precompute's gather rays against plain Embree closest-hit and occlusion loops
//    over the same prepared mesh with the same kind of rays.
#include <benchmark/benchmark.h>

#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "cli/demo_room.h"
#include "engine/gather_operator.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "runtime/relighter.h"
#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

struct PrecomputedRoom {
  Scene scene = scene_from_json(demo_room_scene(), "demo-room.json");
  Precomputed precomputed;
  std::unique_ptr<Relighter> relighter;
  std::vector<float> irradiance;

  PrecomputedRoom() {
    PrecomputeOptions options;
    options.progress = false;
    precomputed = precompute_transfer(scene, options);
    relighter = std::make_unique<Relighter>(in_memory_view(precomputed), scene);
    irradiance.resize(3 * relighter->receivers());
  }
};

PrecomputedRoom& room() {
  static PrecomputedRoom r;
  return r;
}

void BM_RelightFrame(benchmark::State& state) {
  PrecomputedRoom& r = room();
  LightingState s = r.relighter->state();
  int frame = 0;
  for (auto _ : state) {
    // Every dimmer changes every frame (a counter per luminaire would repeat the same values
    // each frame with an even number of luminaires, and time only the final sum).
    const double dimmer = (++frame % 2) ? 1.0 : 0.5;
    for (LuminaireState& l : s.luminaires) l.dimmer = dimmer;
    r.relighter->set_state(s);
    r.relighter->relight(r.irradiance);
  }
  state.SetBytesProcessed(
      static_cast<std::int64_t>(state.iterations() * r.relighter->transfer_bytes()));
  state.counters["receivers"] = static_cast<double>(r.relighter->receivers());
}
BENCHMARK(BM_RelightFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StreamReadSameBytes(benchmark::State& state) {
  const std::size_t bytes = room().relighter->transfer_bytes();
  std::vector<std::uint64_t> buffer(bytes / sizeof(std::uint64_t), 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, buffer.size(), 1 << 14), std::uint64_t{0},
        [&](const auto& range, std::uint64_t sum) {
          return std::accumulate(buffer.begin() + range.begin(), buffer.begin() + range.end(), sum);
        },
        std::plus<std::uint64_t>()));
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * buffer.size() * 8));
}
BENCHMARK(BM_StreamReadSameBytes)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReaimAndRelight(benchmark::State& state) {
  PrecomputedRoom& r = room();
  LightingState s = r.relighter->state();
  int frame = 0;
  for (auto _ : state) {
    const double t = 0.3 * (++frame % 7);
    s.luminaires[2].aim = normalize(Vec3{-0.35 + t, -0.75, -0.55});
    s.luminaires[2].c0 = normalize(cross(s.luminaires[2].aim, Vec3{0, 0, 1}));
    r.relighter->set_state(s);
    r.relighter->relight(r.irradiance);
  }
}
BENCHMARK(BM_ReaimAndRelight)->Unit(benchmark::kMillisecond)->UseRealTime();

// The gather's rays and plain Embree loops over the same prepared mesh.
struct PreparedRoom {
  Scene scene = scene_from_json(demo_room_scene(), "demo-room.json");
  PreparedMesh mesh = prepare_scene_mesh(scene);
  Receivers receivers = make_receivers(scene, mesh);
  TracedScene traced = build_traced_scene(mesh, scene.materials);
  std::vector<Ray> rays;

  PreparedRoom() {
    Pcg32 rng(5, 2);
    for (std::size_t r = 0; r < receivers.vertex_count; ++r) {
      for (int k = 0; k < 64; ++k) {
        const Vec3 d =
            frame_from_normal(receivers.normals[r])
                .to_world(sample_cosine_hemisphere(rng.next_double(), rng.next_double()));
        rays.push_back({offset_from_surface(receivers.positions[r], receivers.normals[r]), d});
      }
    }
  }
};

PreparedRoom& prepared() {
  static PreparedRoom p;
  return p;
}

void BM_GatherOperatorRays(benchmark::State& state) {
  PreparedRoom& p = prepared();
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const GatherOperator g = build_gather_operator(p.receivers, p.mesh, p.traced, 64, 64, 1, false);
    rays = g.rays;
  }
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GatherOperatorRays)->Unit(benchmark::kMillisecond)->UseRealTime();

template <bool kOcclusion>
void BM_PlainEmbreeLoop(benchmark::State& state) {
  PreparedRoom& p = prepared();
  for (auto _ : state) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.rays.size(), 4096),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if constexpr (kOcclusion) {
                            benchmark::DoNotOptimize(p.traced.opaque.occluded(p.rays[i]));
                          } else {
                            benchmark::DoNotOptimize(p.traced.opaque.intersect(p.rays[i]));
                          }
                        }
                      });
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(p.rays.size()),
                                                benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PlainEmbreeLoop<false>)
    ->Name("BM_PlainEmbreeIntersectSameRays")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_PlainEmbreeLoop<true>)
    ->Name("BM_PlainEmbreeOccludedSameRays")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace relight
