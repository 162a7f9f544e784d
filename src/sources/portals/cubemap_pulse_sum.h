// Pulse records (cubemap_encoding.h: the kept cells' indices, then their uint8 levels) and the
// Haar records that share their layout (a second scale, int8 details), as cubemap_sum.cpp reads
// them: their entries, their sum on any processor and index width (sparse_dot), and the pulse sum
// with AVX2 and FMA for 2-byte indices. Included by cubemap_sum.cpp alone, which inlines them into
// its per-record loop (internal linkage, see cubemap_sum_common.h); the writer is
// cubemap_pulse.cpp.
#pragma once

#include <immintrin.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/rgb.h"
#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/cubemap_sum_common.h"

namespace relight::cubemap_detail {
namespace {

// Calls visit(index, value) for each entry, checking indices are increasing and < limit.
template <class F>
void for_each_entry(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t w = cubemap_code_index_bytes(n), limit = cell_count(n);
  const EntryValue value = entry_value(rec, n);
  std::size_t previous = 0;
  for (std::size_t e = 0; e < rec.count; ++e) {
    const std::size_t k = get_uint(rec.indices.data() + e * w, w);
    if (k >= limit || (e > 0 && k <= previous)) bad_record("index out of range or not increasing");
    previous = k;
    visit(k, value(k, rec.values[e]));
  }
}

// The hot loop: Σ table[k]·value(k, q) over the entries, in float: a texel is one 4-float
// load, and four accumulators take the entries in turn (with one, each entry waits four cycles on
// the previous add). A face average (k & face_mask == 0) is uint8 levels × scale, a Haar detail
// int8 levels × detail scale; a pulse record has no details (face_mask 0).
template <std::size_t W>
Rgb sparse_dot(const CubemapRecord& rec, const std::vector<ShellTexel>& table,
               const EntryValue& value) {
  const std::uint8_t* idx = rec.indices.data();
  const std::uint8_t* val = rec.values.data();
  const std::size_t limit = table.size(), mask = value.face_mask;
  const auto scale = static_cast<float>(value.scale);
  const auto detail_scale = static_cast<float>(value.detail_scale);
  __m128 acc[4] = {_mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
  const auto add = [&](std::size_t e, __m128& sum) {
    const std::size_t k = get_uint(idx + e * W, W);
    if (k >= limit) bad_record("index out of range");
    const bool detail = (k & mask) != 0;
    const float level = detail ? static_cast<float>(static_cast<std::int8_t>(val[e])) * detail_scale
                               : static_cast<float>(val[e]) * scale;
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_load_ps(table[k].rgb), _mm_set1_ps(level)));
  };
  std::size_t e = 0;
  for (; e + 4 <= rec.count; e += 4) {
    add(e, acc[0]);
    add(e + 1, acc[1]);
    add(e + 2, acc[2]);
    add(e + 3, acc[3]);
  }
  for (; e < rec.count; ++e) add(e, acc[0]);
  alignas(16) float sum[4];
  _mm_store_ps(sum, _mm_add_ps(_mm_add_ps(acc[0], acc[1]), _mm_add_ps(acc[2], acc[3])));
  return {sum[0], sum[1], sum[2]};
}

std::uint16_t index16(const std::uint8_t* idx, std::size_t e) {
  return word16(idx + 2 * e);
}

// The largest of `count` little-endian uint16 indices, sixteen at a time: checked before the
// sum reads the shell, so that the sum itself tests nothing.
__attribute__((target("avx2"))) std::uint32_t largest_index16(const std::uint8_t* idx,
                                                              std::size_t count) {
  if (count < 16) {
    std::uint32_t largest = 0;
    for (std::size_t e = 0; e < count; ++e)
      largest = std::max(largest, std::uint32_t{index16(idx, e)});
    return largest;
  }
  const auto* sixteen = reinterpret_cast<const __m256i*>(idx);  // 16 indices in 32 bytes
  __m256i most = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idx + 2 * (count - 16)));
  for (std::size_t e = 0; e + 16 < count; e += 16)
    most = _mm256_max_epu16(most, _mm256_loadu_si256(sixteen + e / 16));
  __m128i half = _mm_max_epu16(_mm256_castsi256_si128(most), _mm256_extracti128_si256(most, 1));
  // The horizontal maximum of eight uint16: minpos of their complements.
  half = _mm_minpos_epu16(_mm_xor_si128(half, _mm_set1_epi16(-1)));
  return 0xffffu - static_cast<std::uint32_t>(_mm_cvtsi128_si32(half) & 0xffff);
}

// The texels of entries e and e + 1 in one register.
__attribute__((target("avx2"))) __m256 texel_pair(const ShellTexel* texel, const std::uint8_t* idx,
                                                  std::size_t e) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(texel[index16(idx, e)].rgb)),
                              _mm_load_ps(texel[index16(idx, e + 1)].rgb), 1);
}

// A pulse record with 2-byte indices (the default N = 32; nearly every record of a room seen
// through a window), with AVX2 and FMA: the indices checked at once, then two entries a step,
// their texels in one 8-float register and their levels spread from eight converted at a time
// by a permute, multiplied-added into four accumulators; the record's scale applied once at the
// end (Σ q·S/255·L = S/255·Σ q·L). Faster than sparse_dot (a range test, a select on the entry's
// kind and a scale multiply an entry), and faster again with the tail's levels read as below
// (measured: docs/decisions.md). Confining the lookups to 16 kB of the 96 kB shell changes
// nothing: the loop is bound by its instructions, not the cache. Test:
// CubemapEncoding.PulseDotOfEveryLengthEqualsDenseDotTo1e6AndChecksEveryIndex.
__attribute__((target("avx2,fma"))) Rgb pulse_dot16_avx2(const CubemapRecord& rec,
                                                         const std::vector<ShellTexel>& table,
                                                         float scale) {
  const std::uint8_t* idx = rec.indices.data();
  const std::uint8_t* val = rec.values.data();
  const std::size_t count = rec.count;
  if (largest_index16(idx, count) >= table.size()) bad_record("index out of range");
  const ShellTexel* texel = table.data();
  const __m256i spread[4] = {
      _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3),
      _mm256_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5), _mm256_setr_epi32(6, 6, 6, 6, 7, 7, 7, 7)};
  // Four accumulators, as an FMA waits four cycles on its accumulator (two measured the same).
  __m256 acc[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(),
                   _mm256_setzero_ps()};
  std::size_t e = 0;
  for (; e + 8 <= count; e += 8) {
    const __m256 levels = levels_as_floats(eight_bytes(val + e));
    for (int j = 0; j < 4; ++j)
      acc[j] = _mm256_fmadd_ps(texel_pair(texel, idx, e + 2 * static_cast<std::size_t>(j)),
                               _mm256_permutevar8x32_ps(levels, spread[j]), acc[j]);
  }
  // The last 0-7 entries: whole pairs into the accumulators, then one texel alone. Their
  // levels are read as the eight bytes that end the record (a record of m ≥ 1 entries holds
  // 7 + 3m ≥ 8 bytes) and shifted down, instead of a call to copy 0-7 bytes a record (the sum 3 %
  // faster).
  const std::size_t rest = count - e;
  const __m256 levels =
      levels_as_floats(rest == 0 ? 0 : eight_bytes(val + count - 8) >> (8 * (8 - rest)));
  for (int j = 0; e + 2 <= count; e += 2, ++j)
    acc[j] = _mm256_fmadd_ps(texel_pair(texel, idx, e), _mm256_permutevar8x32_ps(levels, spread[j]),
                             acc[j]);
  const __m256 all = _mm256_add_ps(_mm256_add_ps(acc[0], acc[1]), _mm256_add_ps(acc[2], acc[3]));
  __m128 sum = _mm_add_ps(_mm256_castps256_ps128(all), _mm256_extractf128_ps(all, 1));
  if (e < count)
    sum = _mm_fmadd_ps(_mm_load_ps(texel[index16(idx, e)].rgb),
                       _mm_set1_ps(static_cast<float>(val[e])), sum);
  alignas(16) float out[4];
  _mm_store_ps(out, _mm_mul_ps(sum, _mm_set1_ps(scale)));
  return {out[0], out[1], out[2]};
}

}  // namespace
}  // namespace relight::cubemap_detail
