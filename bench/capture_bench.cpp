// `relight capture` speed: two brackets of five 12-megapixel JPEGs (4000 × 3000, a
// synthetic capture of Blender's interior.exr, tests/support/synthetic_capture.h) → a
// 1024 × 512 map, against a baseline measured in the same run: decoding the ten JPEGs alone,
// which every capture must do. The bound is 20 s on 2 cores.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "capture/capture.h"
#include "image/photo.h"
#include "light/environment_map_io.h"
#include "support/synthetic_capture.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

const std::filesystem::path kInterior =
    "/usr/share/blender/datafiles/studiolights/world/interior.exr";

// The brackets, made once (tens of seconds) and kept for both benchmarks.
struct Brackets {
  testing::TempDir dir;
  testing::SyntheticCapture photos;
};

const Brackets* brackets() {
  static const std::unique_ptr<Brackets> made = [] {
    if (!std::filesystem::exists(kInterior)) return std::unique_ptr<Brackets>();
    auto b = std::make_unique<Brackets>();
    testing::SyntheticCaptureSpec spec;
    spec.width = 4000;
    spec.height = 3000;
    spec.radius = 1450;
    spec.supersample = 1;
    b->photos = testing::make_synthetic_capture(
        testing::within_bracket(read_environment_map(kInterior), spec), b->dir.path(), spec);
    return b;
  }();
  return made.get();
}

void BM_CaptureDecodeTenJpegs(benchmark::State& state) {
  const Brackets* b = brackets();
  if (b == nullptr) {
    state.SkipWithError("interior.exr (Debian blender-data) not found");
    return;
  }
  for (auto _ : state) {
    for (const auto* files : {&b->photos.front, &b->photos.back}) {
      for (const std::filesystem::path& f : *files) benchmark::DoNotOptimize(read_photo(f));
    }
  }
}
BENCHMARK(BM_CaptureDecodeTenJpegs)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_Capture12MegapixelBrackets(benchmark::State& state) {
  const Brackets* b = brackets();
  if (b == nullptr) {
    state.SkipWithError("interior.exr (Debian blender-data) not found");
    return;
  }
  CaptureOptions options;
  options.front = b->photos.front;
  options.back = b->photos.back;
  options.illuminance_lux = 100;
  for (auto _ : state) benchmark::DoNotOptimize(capture_environment(options));
}
BENCHMARK(BM_Capture12MegapixelBrackets)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
}  // namespace relight
