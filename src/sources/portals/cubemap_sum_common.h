// The helpers that the readers and sums of the four cubemap records (cubemap_encoding.h) share:
// little-endian reads, a malformed record's error, an entry's value, and the AVX2 steps of the
// pulse, run and rectangle sums. Included by cubemap_sum.cpp alone, with the kinds' *_sum.h.
// Internal linkage, and `inline` only where a sum asks for it, on purpose: GCC then inlines and
// clones them into the block loop of add_receiver_cubemaps as it would in one file; with external
// linkage, even for a helper as small as cell_count, it decides differently and the loop's object
// code changes.
#pragma once

#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "common/input_error.h"
#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/cubemap_face.h"

namespace relight::cubemap_detail {
namespace {

std::uint32_t get_uint(const std::uint8_t* p, std::size_t width) {
  std::uint32_t v = 0;
  for (std::size_t b = 0; b < width; ++b) v |= std::uint32_t{p[b]} << (8 * b);
  return v;
}

[[noreturn]] void bad_record(const std::string& reason) {
  throw InputError("cubemap record: " + reason);
}

// The value of entry byte q: unsigned, or signed for a Haar detail (index in face ≠ 0).
struct EntryValue {
  double scale = 0, detail_scale = 0;
  std::size_t face_mask = 0;
  double operator()(std::size_t k, std::uint8_t q) const {
    return (k & face_mask) != 0 ? static_cast<std::int8_t>(q) * detail_scale : q * scale;
  }
};

EntryValue entry_value(const CubemapRecord& rec, int n) {
  if (rec.kind == CubemapCodeKind::kHaar)
    return {rec.scale / kPulseLevels, rec.detail_scale / kHaarLevels, std::size_t(n) * n - 1};
  return {rec.scale / kPulseLevels, 0.0, 0};
}

// The 16-bit word at `p` (little-endian, as x86).
std::uint16_t word16(const std::uint8_t* p) {
  std::uint16_t v;
  std::memcpy(&v, p, 2);
  return v;
}

// Eight uint8 levels as floats.
__attribute__((target("avx2"))) __m256 levels_as_floats(std::uint64_t eight) {
  return _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(eight))));
}

// Eight bytes from p (unaligned).
std::uint64_t eight_bytes(const std::uint8_t* p) {
  std::uint64_t eight;
  std::memcpy(&eight, p, 8);
  return eight;
}

// Σ of eight floats.
__attribute__((target("avx2"))) float horizontal_sum(__m256 v) {
  __m128 s = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  s = _mm_add_ps(s, _mm_movehl_ps(s, s));
  s = _mm_add_ss(s, _mm_movehdup_ps(s));
  return _mm_cvtss_f32(s);
}

}  // namespace
}  // namespace relight::cubemap_detail
