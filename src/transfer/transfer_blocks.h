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

}  // namespace relight
