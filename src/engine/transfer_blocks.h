// The stored layout of SH transfer, designed for the run-time weighted sum: receivers in blocks
// of kBlock; within a block, for each basis k
// and colour channel c, kBlock contiguous values. The relighter streams a luminaire's
// blocks once per frame and accumulates acc_c[i] += W[k][c] · T[block][k][c][i], a loop
// over i that vectorises. The last block is zero-padded.
//
// The values are stored as 32-bit floats or as binary16 (scene "precompute": {"storage"}):
// the sum is bound by the bytes it streams, and binary16 halves them. A binary16
// value stands for scale · value, the scale a power of two chosen when packing so that the
// largest magnitude lands in [2¹⁴, 2¹⁵): binary16 keeps its 11 significant bits from there down
// to 2⁻¹⁴, a range of 2²⁹, so no value that matters to the sum leaves the normal range, and the
// scale folds into the weights (no multiply in the loop). Rounding to nearest leaves each value
// within 2⁻¹¹ relative. The loop converts in registers (F16C, when the processor has it; a
// table otherwise). Pinned by tests/engine/transfer_blocks_test.cpp and, probe against fp32, by
// tests/cli/transfer_storage_test.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "common/cpu_features.h"
#include "store/rlt_format.h"

namespace relight {

inline constexpr std::size_t kBlock = 64;

constexpr std::size_t block_count(std::size_t receivers) {
  return (receivers + kBlock - 1) / kBlock;
}
// Floats in one luminaire's blocked transfer for `channels` (1 or 3) and K bases.
constexpr std::size_t blocked_floats(std::size_t receivers, std::size_t k, std::size_t channels) {
  return block_count(receivers) * k * channels * kBlock;
}

// Packs per-channel (receivers × K) matrices into the blocked layout; a channel may be a block of
// columns of a larger matrix (Eigen::Ref binds to it without a copy).
std::vector<float> pack_blocks(std::initializer_list<Eigen::Ref<const Eigen::MatrixXf>> channels);

// The hot loop of every source's weighted sum: acc_c[i] += Σ_k w[3k + c] · T[k][c][i] over one
// block of RGB transfer `t` in the blocked layout (K bases, each three channels of kBlock
// receivers). Allocates nothing; the loop over i vectorises.
inline void add_weighted_block(const float* t, std::size_t k, const float* w,
                               float (&acc)[3][kBlock]) {
  for (std::size_t basis = 0; basis < k; ++basis) {
    for (std::size_t c = 0; c < 3; ++c) {
      const float weight = w[3 * basis + c];
      const float* tc = t + (3 * basis + c) * kBlock;
      for (std::size_t i = 0; i < kBlock; ++i) acc[c][i] += weight * tc[i];
    }
  }
}

enum class TransferStorage { fp32, fp16 };
// The scene's "storage" value ("fp16" or "fp32", scene/scene.h PrecomputeSettings).
inline TransferStorage transfer_storage_named(const std::string& name) {
  return name == "fp16" ? TransferStorage::fp16 : TransferStorage::fp32;
}

// A source's blocked transfer as the run time reads it (a view into the .rlt or into a
// PackedTransfer): `f32`, or `f16` standing for scale · value.
struct BlockedTransfer {
  std::span<const float> f32;
  std::span<const RltHalf> f16;
  float scale = 1;

  bool half() const { return !f16.empty(); }
  std::size_t size() const { return half() ? f16.size() : f32.size(); }
  std::size_t size_bytes() const { return f32.size_bytes() + f16.size_bytes(); }
  std::span<const std::byte> bytes() const {
    return half() ? std::as_bytes(f16) : std::as_bytes(f32);
  }
  // Values [first, first + out.size()) as floats.
  void copy_to(std::size_t first, std::span<float> out) const;
};

// What the precompute packs and the file stores of one source.
struct PackedTransfer {
  std::vector<float> f32;
  std::vector<RltHalf> f16;
  float scale = 1;

  BlockedTransfer view() const { return {f32, f16, scale}; }
  std::size_t size_bytes() const { return view().size_bytes(); }
};

// `blocked` (pack_blocks) kept as floats or converted to scaled binary16.
PackedTransfer store_blocks(std::vector<float> blocked, TransferStorage storage);
// The same, binary16 scaled for `largest` (at least the largest magnitude in `blocked`: the
// section's, when ranks each pack their blocks of it).
PackedTransfer store_blocks(std::vector<float> blocked, TransferStorage storage, float largest);
float largest_magnitude(std::span<const float> values);

// The power of two a section of binary16 transfer is scaled by, from its largest magnitude.
float half_scale(float largest_magnitude);

// add_weighted_block over one block of binary16 transfer standing for scale · value: with F16C
// (the caller checks has_f16c()) or through a table.
void add_weighted_half_block(const RltHalf* t, std::size_t k, const float* w, float scale,
                             float (&acc)[3][kBlock], bool f16c);

// The bytes of block b of `t` (K bases) that add_weighted_block reads.
std::span<const std::byte> block_bytes(const BlockedTransfer& t, std::size_t b, std::size_t k);

// add_weighted_block over block b of `t`, whichever its storage.
void add_weighted_block(const BlockedTransfer& t, std::size_t b, std::size_t k, const float* w,
                        float (&acc)[3][kBlock]);

}  // namespace relight
