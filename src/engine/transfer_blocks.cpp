#include "engine/transfer_blocks.h"

namespace relight {

std::vector<float> pack_blocks(const std::vector<const Eigen::MatrixXf*>& channels) {
  const std::size_t n = static_cast<std::size_t>(channels.front()->rows());
  const std::size_t k = static_cast<std::size_t>(channels.front()->cols());
  const std::size_t c_count = channels.size();
  std::vector<float> out(blocked_floats(n, k, c_count), 0.0f);
  for (std::size_t b = 0; b < block_count(n); ++b) {
    for (std::size_t basis = 0; basis < k; ++basis) {
      for (std::size_t c = 0; c < c_count; ++c) {
        float* dst = out.data() + ((b * k + basis) * c_count + c) * kBlock;
        const Eigen::MatrixXf& m = *channels[c];
        for (std::size_t i = 0; i < kBlock && b * kBlock + i < n; ++i) {
          dst[i] = m(static_cast<Eigen::Index>(b * kBlock + i), static_cast<Eigen::Index>(basis));
        }
      }
    }
  }
  return out;
}

}  // namespace relight
