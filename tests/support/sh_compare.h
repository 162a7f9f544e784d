// Largest magnitudes of coefficient vectors, for comparing SH projections in tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace relight::testing {

inline double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

inline double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace relight::testing
