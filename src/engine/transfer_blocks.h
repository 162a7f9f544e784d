// The stored layout of SH transfer, designed for the run-time weighted sum
// (ARCHITECTURE §4.6): receivers in blocks of kBlock; within a block, for each basis k
// and colour channel c, kBlock contiguous floats. The relighter streams a luminaire's
// blocks once per frame and accumulates acc_c[i] += W[k][c] · T[block][k][c][i], a loop
// over i that vectorises. The last block is zero-padded.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace relight {

inline constexpr std::size_t kBlock = 64;

constexpr std::size_t block_count(std::size_t receivers) {
  return (receivers + kBlock - 1) / kBlock;
}
// Floats in one luminaire's blocked transfer for `channels` (1 or 3) and K bases.
constexpr std::size_t blocked_floats(std::size_t receivers, std::size_t k, std::size_t channels) {
  return block_count(receivers) * k * channels * kBlock;
}

// Packs per-channel (receivers × K) matrices into the blocked layout.
std::vector<float> pack_blocks(const std::vector<const Eigen::MatrixXf*>& channels);

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

}  // namespace relight
