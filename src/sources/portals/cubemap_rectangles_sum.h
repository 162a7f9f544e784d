// Face-rectangle records (cubemap_encoding.h: the bounding rectangle of the kept cells on each
// face, then one uint8 level a cell of it, row by row) as cubemap_sum.cpp reads them: the header
// reader that checks a record, the cell iteration, and its sums, on any processor and with AVX2
// and FMA. Included by cubemap_sum.cpp alone, which inlines them into its per-record loop
// (internal linkage, see cubemap_sum_common.h); the encoder is cubemap_rectangles.cpp.
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

// Reads the header of the rectangle record at bytes[0] (kind 4) for face size n into `rec`,
// checking every rectangle (so the sums test nothing): nullptr, or why it is malformed. The
// one check of a rectangle header, for parse_cubemap_record and add_receiver_cubemaps' block
// loop, which inlines it.
[[gnu::always_inline]] inline const char* read_rectangles_header(
    int n, std::span<const std::uint8_t> bytes, CubemapRecord& rec) {
  if (!cubemap_rectangles_fit(n)) return "rectangles for faces of more than 256 cells";
  if (bytes.size() < 6) return "truncated header";
  rec.kind = CubemapCodeKind::kRectangles;
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) return "scale not positive and finite";
  rec.rectangles = bytes[5];
  if (rec.rectangles == 0 || rec.rectangles > 6) return "rectangle count out of range";
  if (bytes.size() < 6 + 5 * rec.rectangles) return "truncated rectangles";
  const std::uint8_t* r = bytes.data() + 6;
  std::size_t levels = 0;
  int previous = -1;
  for (std::size_t j = 0; j < rec.rectangles; ++j, r += 5) {
    const int face = r[0], w = r[3] + 1, h = r[4] + 1;
    if (face <= previous || face > 5 || r[1] + w > n || r[2] + h > n)
      return "rectangle beyond its face or faces out of order";
    previous = face;
    levels += static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  }
  rec.count = levels;
  rec.bytes = cubemap_record_bytes(n, rec.kind, rec.count, rec.rectangles);
  if (bytes.size() < rec.bytes) return "truncated levels";
  rec.indices = bytes.subspan(6, 5 * rec.rectangles);
  rec.values = bytes.subspan(6 + 5 * rec.rectangles, rec.count);
  return nullptr;
}

// Calls visit(cell, level) for each cell of a rectangle record read by read_rectangles_header.
template <class F>
void for_each_rectangle_cell(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t nn = std::size_t(n) * n;
  const std::uint8_t* level = rec.values.data();
  for (std::size_t j = 0; j < rec.rectangles; ++j) {
    const std::uint8_t* r = rec.indices.data() + 5 * j;
    for (int y = r[2]; y <= r[2] + r[4]; ++y)
      for (int x = r[1]; x <= r[1] + r[3]; ++x)
        visit(r[0] * nn + static_cast<std::size_t>(y) * n + x, *level++);
  }
}

// The rows of one rectangle, K = ⌈width/8⌉ steps of eight cells a row (1 ≤ K ≤ 4), added into
// `whole` (the first K − 1 steps) and `last` (the last, its 1-8 levels the eight bytes that end
// the row shifted down: the record's header lies before them). `level` is left after the
// rectangle's levels. K a constant, so a row is straight-line code and only the row loop
// branches.
template <std::size_t K>
[[gnu::always_inline]] inline __attribute__((target("avx2,fma"))) void add_rectangle_rows(
    const std::uint8_t*& level, std::size_t width, std::size_t height, std::size_t cell,
    std::size_t n, const float* const (&plane)[3], __m256 (&whole)[3], __m256 (&last)[3]) {
  const std::size_t shift = 8 * (8 * K - width);
  for (std::size_t y = 0; y < height; ++y, level += width, cell += n) {
    for (std::size_t b = 0; b + 1 < K; ++b) {
      const __m256 q = levels_as_floats(eight_bytes(level + 8 * b));
      for (int c = 0; c < 3; ++c)
        whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + 8 * b), whole[c]);
    }
    const __m256 q = levels_as_floats(eight_bytes(level + width - 8) >> shift);
    for (int c = 0; c < 3; ++c)
      last[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + 8 * (K - 1)), last[c]);
  }
}

// Σ over a rectangle record's cells of level × the shell's cells, per channel (the record's
// scale not applied), with AVX2 and FMA: `rectangles` checked headers of five bytes at
// `header`, then their levels. Each rectangle's rows by add_rectangle_rows for its number of
// eights (faces of up to 32 cells: N = 32, the default, and smaller; wider rows by the runs'
// loop of eights). The planes' padding keeps the cells read past a row that ends the cubemap
// inside (their levels are 0 and the cells after a row's end finite). Always inlined: a call a
// record from add_records_avx2 costs a tenth of the sum. Faster than the same receivers as runs,
// and than a loop of eights a row in place of the constant (measured: docs/decisions.md). Test:
// CubemapEncoding.RectangleDotOfEveryWidthAndPlaceEqualsDenseDotTo1e6AndChecksEveryRectangle.
[[gnu::always_inline]] inline __attribute__((target("avx2,fma"))) Rgb rectangles_sum_avx2(
    const std::uint8_t* header, std::size_t rectangles, const std::uint8_t* level,
    const ShellCubemap& shell) {
  const std::size_t n = static_cast<std::size_t>(shell.n), nn = n * n;
  const float* const plane[3] = {shell.planes[0].data(), shell.planes[1].data(),
                                 shell.planes[2].data()};
  __m256 whole[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  __m256 last[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  for (std::size_t j = 0; j < rectangles; ++j, header += 5) {
    const std::size_t width = header[3] + std::size_t{1}, height = header[4] + std::size_t{1};
    const std::size_t cell = header[0] * nn + header[2] * n + header[1];
    switch ((width + 7) / 8) {
      case 1:
        add_rectangle_rows<1>(level, width, height, cell, n, plane, whole, last);
        break;
      case 2:
        add_rectangle_rows<2>(level, width, height, cell, n, plane, whole, last);
        break;
      case 3:
        add_rectangle_rows<3>(level, width, height, cell, n, plane, whole, last);
        break;
      case 4:
        add_rectangle_rows<4>(level, width, height, cell, n, plane, whole, last);
        break;
      default:
        for (std::size_t y = 0; y < height; ++y, level += width) {
          const std::size_t eights = width & ~std::size_t{7};
          for (std::size_t x = 0; x < width; x += 8) {
            const std::uint64_t bytes =
                x < eights ? eight_bytes(level + x)
                           : eight_bytes(level + width - 8) >> (8 * (8 - (width - eights)));
            const __m256 q = levels_as_floats(bytes);
            for (int c = 0; c < 3; ++c)
              whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + y * n + x), whole[c]);
          }
        }
    }
  }
  return {horizontal_sum(_mm256_add_ps(whole[0], last[0])),
          horizontal_sum(_mm256_add_ps(whole[1], last[1])),
          horizontal_sum(_mm256_add_ps(whole[2], last[2]))};
}

// rectangles_sum_avx2 for one record, not inlined (dot_receiver_cubemap is built for any
// processor).
__attribute__((target("avx2,fma"))) Rgb rectangles_dot_avx2(const CubemapRecord& rec,
                                                            const ShellCubemap& shell) {
  return rectangles_sum_avx2(rec.indices.data(), rec.rectangles, rec.values.data(), shell);
}

// The same on any processor.
Rgb rectangles_dot(const CubemapRecord& rec, const ShellCubemap& shell) {
  float sum[3] = {0, 0, 0};
  for_each_rectangle_cell(rec, shell.n, [&](std::size_t k, std::uint8_t q) {
    for (int c = 0; c < 3; ++c) sum[c] += static_cast<float>(q) * shell.planes[c][k];
  });
  return {sum[0], sum[1], sum[2]};
}

}  // namespace
}  // namespace relight::cubemap_detail
