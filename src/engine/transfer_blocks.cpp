#include "engine/transfer_blocks.h"

#include <Imath/half.h>
#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace relight {

namespace {

float to_float(RltHalf h) {
  Imath::half v;
  v.setBits(h.bits);
  return static_cast<float>(v);
}

// acc_c[i] += Σ_k w[3k + c] · scale · t[k][c][i] over one block of binary16 transfer.
void add_weighted_half_block_table(const RltHalf* t, std::size_t k, const float* w, float scale,
                                   float (&acc)[3][kBlock]) {
  for (std::size_t basis = 0; basis < k; ++basis) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float weight = w[3 * basis + c] * scale;
      const RltHalf* tc = t + (3 * basis + c) * kBlock;
      for (std::size_t i = 0; i < kBlock; ++i) acc[c][i] += weight * to_float(tc[i]);
    }
  }
}

// The same with F16C: eight values converted and multiplied-added a step, the block read in
// its stored order (bases, then channels: one pass forward through memory). Keeping the 24
// accumulators of a channel-outer loop in registers instead reads each block in three strided
// passes, at half the streaming rate (measured: docs/decisions.md; bench/dragon-room.json).
__attribute__((target("avx2,f16c,fma"))) void add_weighted_half_block_f16c(
    const RltHalf* t, std::size_t k, const float* w, float scale, float (&acc)[3][kBlock]) {
  for (std::size_t basis = 0; basis < k; ++basis) {
    for (std::size_t c = 0; c < 3; ++c) {
      const __m256 weight = _mm256_set1_ps(w[3 * basis + c] * scale);
      const RltHalf* tc = t + (3 * basis + c) * kBlock;
      float* a = acc[c];
      for (std::size_t j = 0; j < kBlock; j += 8) {
        const __m128i packed = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tc + j));
        _mm256_storeu_ps(a + j,
                         _mm256_fmadd_ps(weight, _mm256_cvtph_ps(packed), _mm256_loadu_ps(a + j)));
      }
    }
  }
}

}  // namespace

void add_weighted_half_block(const RltHalf* t, std::size_t k, const float* w, float scale,
                             float (&acc)[3][kBlock], bool f16c) {
  if (f16c) {
    add_weighted_half_block_f16c(t, k, w, scale, acc);
  } else {
    add_weighted_half_block_table(t, k, w, scale, acc);
  }
}

void BlockedTransfer::copy_to(std::size_t first, std::span<float> out) const {
  if (!half()) {
    std::copy_n(f32.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
    return;
  }
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = scale * to_float(f16[first + i]);
}

float half_scale(float largest_magnitude) {
  if (!(largest_magnitude > 0) || !std::isfinite(largest_magnitude)) return 1;
  return std::ldexp(1.0f, std::ilogb(largest_magnitude) - 14);
}

float largest_magnitude(std::span<const float> values) {
  float largest = 0;
  for (const float v : values) largest = std::max(largest, std::abs(v));
  return largest;
}

PackedTransfer store_blocks(std::vector<float> blocked, TransferStorage storage) {
  const float largest = storage == TransferStorage::fp16 ? largest_magnitude(blocked) : 0.0f;
  return store_blocks(std::move(blocked), storage, largest);
}

PackedTransfer store_blocks(std::vector<float> blocked, TransferStorage storage, float largest) {
  PackedTransfer out;
  if (storage == TransferStorage::fp32) {
    out.f32 = std::move(blocked);
    return out;
  }
  out.scale = half_scale(largest);
  out.f16.resize(blocked.size());
  const float inverse = 1 / out.scale;  // a power of two: exact
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    out.f16[i].bits = Imath::half(blocked[i] * inverse).bits();
  }
  return out;
}

std::span<const std::byte> block_bytes(const BlockedTransfer& t, std::size_t b, std::size_t k) {
  const std::size_t values = k * 3 * kBlock;
  const std::size_t width = t.half() ? sizeof(RltHalf) : sizeof(float);
  return t.bytes().subspan(b * values * width, values * width);
}

void add_weighted_block(const BlockedTransfer& t, std::size_t b, std::size_t k, const float* w,
                        float (&acc)[3][kBlock]) {
  const std::size_t at = b * k * 3 * kBlock;
  if (!t.half()) {
    add_weighted_block(t.f32.data() + at, k, w, acc);
  } else {
    add_weighted_half_block(t.f16.data() + at, k, w, t.scale, acc, has_f16c());
  }
}

std::vector<float> pack_blocks(std::initializer_list<Eigen::Ref<const Eigen::MatrixXf>> channels) {
  const std::size_t n = static_cast<std::size_t>(channels.begin()->rows());
  const std::size_t k = static_cast<std::size_t>(channels.begin()->cols());
  const std::size_t c_count = channels.size();
  std::vector<float> out(blocked_floats(n, k, c_count), 0.0f);
  for (std::size_t b = 0; b < block_count(n); ++b) {
    for (std::size_t basis = 0; basis < k; ++basis) {
      for (std::size_t c = 0; c < c_count; ++c) {
        float* dst = out.data() + ((b * k + basis) * c_count + c) * kBlock;
        const Eigen::Ref<const Eigen::MatrixXf>& m = *(channels.begin() + c);
        for (std::size_t i = 0; i < kBlock && b * kBlock + i < n; ++i) {
          dst[i] = m(static_cast<Eigen::Index>(b * kBlock + i), static_cast<Eigen::Index>(basis));
        }
      }
    }
  }
  return out;
}

}  // namespace relight
