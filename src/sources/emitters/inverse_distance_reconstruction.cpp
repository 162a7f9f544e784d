#include "sources/emitters/inverse_distance_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

namespace {

std::size_t coefficient_count(std::span<const IncidentSample> samples) {
  if (samples.empty()) throw std::invalid_argument("reconstruct_inverse_distance: no samples");
  const std::size_t k = samples.front().sh.size();
  for (const IncidentSample& s : samples) {
    if (s.sh.size() != k || k == 0) {
      throw std::invalid_argument("reconstruct_inverse_distance: samples of different orders");
    }
  }
  return k;
}

// (d_min / d)^b from squared distances: the normalised weights of Eq. 2.13 scaled by d_min^b,
// which leaves them unchanged and cannot overflow.
double relative_weight(double nearest2, double d2, double exponent) {
  if (nearest2 == 0) return d2 == 0 ? 1 : 0;
  const double ratio2 = nearest2 / d2;
  if (exponent == 2) return ratio2;
  if (exponent == 1) return std::sqrt(ratio2);
  return std::pow(ratio2, 0.5 * exponent);
}

}  // namespace

void reconstruct_inverse_distance(std::span<const IncidentSample> samples,
                                  std::span<const Vec3> points, std::span<Rgb> out,
                                  double exponent) {
  if (!(exponent >= 0) || !std::isfinite(exponent)) {
    throw std::invalid_argument("reconstruct_inverse_distance: exponent must be >= 0");
  }
  if (points.empty()) return;
  const std::size_t k = coefficient_count(samples);
  if (out.size() != points.size() * k) {
    throw std::invalid_argument("reconstruct_inverse_distance: output of the wrong size");
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 64), [&](const auto& range) {
    std::vector<double> d2(samples.size());
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      double nearest2 = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const Vec3 d = points[p] - samples[i].position;
        d2[i] = dot(d, d);
        nearest2 = std::min(nearest2, d2[i]);
      }
      const std::span<Rgb> row = out.subspan(p * k, k);
      std::fill(row.begin(), row.end(), Rgb{});
      double total = 0;
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const double w = relative_weight(nearest2, d2[i], exponent);
        if (w == 0) continue;
        total += w;
        const std::vector<Rgb>& sh = samples[i].sh;
        for (std::size_t j = 0; j < k; ++j) row[j] += w * sh[j];
      }
      for (Rgb& c : row) c = c / total;
    }
  });
}

}  // namespace relight
