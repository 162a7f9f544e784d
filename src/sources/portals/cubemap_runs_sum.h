// Pulse-run records (cubemap_encoding.h: runs of consecutive cells, (start, length) each, then
// one uint8 level a cell) as cubemap_sum.cpp reads them: the header reader and the cell iteration
// that check a record, and its sums, on any processor and with AVX2 and FMA. Included by
// cubemap_sum.cpp alone, which inlines them into its per-record loop (internal linkage, see
// cubemap_sum_common.h); the encoder is cubemap_runs.cpp.
#pragma once

#include <immintrin.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "math/rgb.h"
#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/cubemap_sum_common.h"

namespace relight::cubemap_detail {
namespace {

// Checks a run of a run record: it starts at or after `end` (the previous run's end) and holds
// `length` of the `left` levels not yet taken; `limit` cells in all.
void check_run(std::size_t start, std::size_t length, std::size_t end, std::size_t left,
               std::size_t limit) {
  if (start < end || length == 0 || length > left || start + length > limit)
    bad_record("run out of range, overlapping or beyond the record's levels");
}

// Reads the header of the run record at bytes[0] (kind 3) for face size n into `rec`: nullptr,
// or why it is malformed. The one check of a run header, for parse_cubemap_record and the block
// loop of add_receiver_cubemaps, which inlines it (a call through parse_cubemap_record a record
// costs half that loop's time; measured: docs/decisions.md).
[[gnu::always_inline]] inline const char* read_runs_header(int n,
                                                           std::span<const std::uint8_t> bytes,
                                                           CubemapRecord& rec) {
  const std::size_t w = cubemap_code_index_bytes(n);
  if (bytes.size() < 1 + 4 + 2 * w) return "truncated header";
  rec.kind = CubemapCodeKind::kRuns;
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) return "scale not positive and finite";
  rec.runs = get_uint(bytes.data() + 5, w);
  rec.count = get_uint(bytes.data() + 5 + w, w);
  if (rec.count == 0 || rec.count > cell_count(n)) return "level count out of range";
  if (rec.runs == 0 || rec.runs > rec.count) return "run count out of range";
  rec.bytes = cubemap_record_bytes(n, rec.kind, rec.count, rec.runs);
  if (bytes.size() < rec.bytes) return "truncated runs";
  rec.indices = bytes.subspan(5 + 2 * w, 2 * w * rec.runs);
  rec.values = bytes.subspan(5 + 2 * w + 2 * w * rec.runs, rec.count);
  return nullptr;
}

// Calls visit(cell, level) for each cell of a run record, checking its runs.
template <class F>
void for_each_run_cell(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t w = cubemap_code_index_bytes(n), limit = cell_count(n);
  std::size_t end = 0, used = 0;
  for (std::size_t j = 0; j < rec.runs; ++j) {
    const std::size_t start = get_uint(rec.indices.data() + 2 * j * w, w);
    const std::size_t length = get_uint(rec.indices.data() + (2 * j + 1) * w, w);
    check_run(start, length, end, rec.count - used, limit);
    for (std::size_t i = 0; i < length; ++i) visit(start + i, rec.values[used + i]);
    used += length;
    end = start + length;
  }
  if (used != rec.count) bad_record("runs hold fewer cells than the record's levels");
}

// Σ over a run record's cells of level × the shell's cells, per channel (the record's scale not
// applied), with AVX2 and FMA for 2-byte starts and lengths: `runs` (start, length) pairs at
// `table`, then `levels` levels. Each run eight cells at a time: their levels converted at once
// and multiplied-added with eight consecutive floats of each of the shell's planes (no lookup,
// no permute). A run's last 1-7 levels are the eight bytes that end them shifted down (the
// record's header lies before its levels, so the bytes read stay inside it), and the planes'
// padding keeps the cells read past a run that ends the cubemap inside (their levels are 0). The
// whole eights and the last few go to separate sums. Faster than the same cells as pulse
// records, and faster again by blocks through add_receiver_cubemaps (measured:
// docs/decisions.md). Taking each run's first sixteen cells as two eights without a branch on its
// length, to spare the mispredicted loop exits, runs slower. Test:
// CubemapEncoding.RunDotOfEveryLengthAndGapEqualsDenseDotTo1e6AndChecksEveryRun.
__attribute__((target("avx2,fma"))) inline Rgb runs_sum16_avx2(const std::uint8_t* table,
                                                               std::size_t runs,
                                                               const std::uint8_t* level,
                                                               std::size_t levels,
                                                               const ShellCubemap& shell) {
  const std::size_t limit = cell_count(shell.n);
  const float* plane[3] = {shell.planes[0].data(), shell.planes[1].data(), shell.planes[2].data()};
  __m256 whole[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  __m256 last[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  std::size_t end = 0, used = 0;
  for (std::size_t j = 0; j < runs; ++j) {
    const std::size_t start = word16(table + 4 * j), length = word16(table + 4 * j + 2);
    check_run(start, length, end, levels - used, limit);
    std::size_t i = 0;
    for (; i + 8 <= length; i += 8) {
      const __m256 q = levels_as_floats(eight_bytes(level + i));
      for (int c = 0; c < 3; ++c)
        whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + start + i), whole[c]);
    }
    if (i < length) {
      const __m256 q =
          levels_as_floats(eight_bytes(level + length - 8) >> (8 * (8 - (length - i))));
      for (int c = 0; c < 3; ++c)
        last[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + start + i), last[c]);
    }
    level += length;
    used += length;
    end = start + length;
  }
  if (used != levels) bad_record("runs hold fewer cells than the record's levels");
  return {horizontal_sum(_mm256_add_ps(whole[0], last[0])),
          horizontal_sum(_mm256_add_ps(whole[1], last[1])),
          horizontal_sum(_mm256_add_ps(whole[2], last[2]))};
}

// The same on any processor and index width.
Rgb runs_dot(const CubemapRecord& rec, const ShellCubemap& shell) {
  float sum[3] = {0, 0, 0};
  for_each_run_cell(rec, shell.n, [&](std::size_t k, std::uint8_t q) {
    for (int c = 0; c < 3; ++c) sum[c] += static_cast<float>(q) * shell.planes[c][k];
  });
  return {sum[0], sum[1], sum[2]};
}

}  // namespace
}  // namespace relight::cubemap_detail
