// The visibility cuts' merge over the paper's height encoding against the previous methods'
// index encoding (Iwasaki et al., Cyberworlds, §V.A.2–3; math/
// cut_encoding.h, math/cut_merge.h): the same cuts of a 32,768-direction tree — the samples of
// a visibility cut field around a point (caps of an object's silhouette seen from nearby
// points, ragged at their edges) and a receiver's self-visibility (its horizon) — interpolated
// eight at a time, as a field is around a receiver, and a receiver's cut multiplied by three
// such fields, as a product at a receiver near three objects. Counters: the bytes of each
// encoding and the nodes merged a second. Run both in one process and compare their ratio
// (docs/performance.md, "Visibility cuts").
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "math/cut_encoding.h"
#include "math/cut_merge.h"
#include "math/direction_cut.h"
#include "math/direction_tree.h"
#include "math/frame.h"

namespace relight {
namespace {

constexpr std::size_t kDirections = 32768;
constexpr std::size_t kFieldSamples = 64;

struct CutSet {
  DirectionTree tree;
  HeightCuts height;  // cut 0: the horizon; 1 …: the field's samples
  IndexCuts index;
};

const CutSet& cut_set() {
  static const CutSet set = [] {
    CutSet s;
    s.tree = build_direction_tree(repulsed_directions(kDirections, 4));
    s.height = make_height_cuts(s.tree);
    const std::size_t n = s.tree.leaf_count();
    std::vector<float> v(n);
    const Vec3 up = normalize(Vec3{0.05, 1, 0.02});
    for (std::size_t i = 0; i < n; ++i) v[i] = dot(s.tree.leaves[i], up) > 0 ? 1.0f : 0.0f;
    append_cut(s.height, make_direction_cut(s.tree, v, 0));
    for (std::size_t k = 0; k < kFieldSamples; ++k) {
      // An object 12–20° across seen from points a little apart, its outline ragged (legs,
      // a backrest) by a wobble of the cap's edge with the azimuth about its axis.
      const std::size_t column = k % 8, row = k / 8;  // a grid of 8 × 8 viewpoints
      const double a = 0.04 * static_cast<double>(column), b = 0.04 * static_cast<double>(row);
      const Vec3 axis = normalize(Vec3{0.6 + a, 0.3, -0.7 + b});
      const Frame f = frame_from_normal(axis);
      const double half = (6.0 + 0.05 * static_cast<double>(k)) * kPi / 180;
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 d = s.tree.leaves[i];
        const Vec3 local = f.to_local(d);
        const double wobble = 1 + 0.25 * std::sin(5 * std::atan2(local.y, local.x));
        v[i] = std::acos(std::clamp(local.z, -1.0, 1.0)) < half * wobble ? 0.0f : 1.0f;
      }
      append_cut(s.height, make_direction_cut(s.tree, v, 0));
    }
    s.index = index_encoded(s.height.view());
    return s;
  }();
  return set;
}

// Eight field samples around a point and their weights.
template <typename View>
std::array<WeightedCutOf<View>, 8> samples_around(const View& view, std::size_t at) {
  constexpr float kWeights[8] = {0.3f, 0.1f, 0.05f, 0.15f, 0.1f, 0.1f, 0.12f, 0.08f};
  std::array<WeightedCutOf<View>, 8> out;
  for (std::size_t j = 0; j < 8; ++j) {
    out[j] = {&view, 1 + (at + (j & 1) + 8 * (j >> 1)) % kFieldSamples, kWeights[j]};
  }
  return out;
}

template <typename View>
void count(benchmark::State& state, const View& view, std::uint64_t nodes) {
  state.counters["encoded_bytes"] = static_cast<double>(view.bytes());
  state.counters["nodes_per_s"] =
      benchmark::Counter(static_cast<double>(nodes), benchmark::Counter::kIsRate);
}

template <typename View>
void interpolate_eight(benchmark::State& state, const View& view) {
  ValueCut out;
  std::uint64_t nodes = 0;
  std::size_t at = 0;
  for (auto _ : state) {
    const auto operands = samples_around(view, at++ % kFieldSamples);
    interpolate_cuts(operands, out);
    benchmark::DoNotOptimize(out.value.data());
    for (const auto& o : operands) nodes += view.first[o.cut + 1] - view.first[o.cut];
  }
  count(state, view, nodes);
}

template <typename View>
void product_of_three(benchmark::State& state, const View& view) {
  std::array<ValueCut, 3> fields;
  ValueCut out;
  std::uint64_t nodes = 0;
  std::size_t at = 0;
  for (auto _ : state) {
    for (std::size_t f = 0; f < 3; ++f) {
      const auto operands = samples_around(view, (at + 20 * f) % kFieldSamples);
      interpolate_cuts(operands, fields[f]);
      for (const auto& o : operands) nodes += view.first[o.cut + 1] - view.first[o.cut];
    }
    ++at;
    const ValueCut* factors[] = {&fields[0], &fields[1], &fields[2]};
    multiply_cuts(view, 0, factors, out);
    benchmark::DoNotOptimize(out.value.data());
  }
  count(state, view, nodes);
}

void BM_CutsInterpolateHeightEncoded(benchmark::State& state) {
  const HeightCutsView view = cut_set().height.view();
  interpolate_eight(state, view);
}
BENCHMARK(BM_CutsInterpolateHeightEncoded)->Unit(benchmark::kMicrosecond);

void BM_CutsInterpolateIndexEncoded(benchmark::State& state) {
  const IndexCutsView view = cut_set().index.view();
  interpolate_eight(state, view);
}
BENCHMARK(BM_CutsInterpolateIndexEncoded)->Unit(benchmark::kMicrosecond);

void BM_CutsProductHeightEncoded(benchmark::State& state) {
  const HeightCutsView view = cut_set().height.view();
  product_of_three(state, view);
}
BENCHMARK(BM_CutsProductHeightEncoded)->Unit(benchmark::kMicrosecond);

void BM_CutsProductIndexEncoded(benchmark::State& state) {
  const IndexCutsView view = cut_set().index.view();
  product_of_three(state, view);
}
BENCHMARK(BM_CutsProductIndexEncoded)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace relight
