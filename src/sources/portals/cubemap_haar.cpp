// The encoder's side of per-face Haar records (cubemap_encoding.h, Yue et al. 2009 §4.1.2): a
// receiver's cells transformed face by face (math/haar.h) and turned into amplitudes in cell units,
// and the two scales they are quantised against.
#include "sources/portals/cubemap_haar.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/haar.h"

namespace relight::cubemap_detail {
namespace {

// Orthonormal per-face Haar coefficients turned into amplitudes a_k = T_k / S_k (in place).
void to_amplitudes(std::span<double> coefficients, int n) {
  for (std::size_t start = 0; start < coefficients.size(); start += std::size_t(n) * n)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        coefficients[start + std::size_t(r) * n + c] /= haar2d_support(n, r, c);
}

}  // namespace

Quantiser haar_amplitudes(int n, std::span<const double> cells, double threshold,
                          CubemapEncodeScratch& scratch) {
  std::vector<double>& amp = scratch.coefficients;
  amp.assign(cells.begin(), cells.end());
  scratch.row.resize(n);
  haar2d_forward_faces(amp, n, scratch.row);
  to_amplitudes(amp, n);
  Quantiser haar;
  haar.face_mask = std::size_t(n) * n - 1;
  haar.threshold = threshold;
  double mean_max = 0.0, detail_max = 0.0;
  for (std::size_t k = 0; k < amp.size(); ++k) {
    if (haar.is_detail(k))
      detail_max = std::max(detail_max, std::abs(amp[k]));
    else
      mean_max = std::max(mean_max, amp[k]);
  }
  haar.scale = scale_at_least(mean_max);
  haar.detail_scale = scale_at_least(detail_max);
  return haar;
}

}  // namespace relight::cubemap_detail
