// Shared helpers for the math tests: deterministic random directions, rotations and SH vectors.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/mat3.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/vec3.h"

namespace relight::test {

inline Vec3 random_direction(Pcg32& rng) {
  const double u1 = rng.next_double();
  return sample_uniform_sphere(u1, rng.next_double());
}

// Uniformly distributed rotation from a random unit quaternion (Shoemake, Graphics Gems III).
inline Mat3 random_rotation(Pcg32& rng) {
  const double u1 = rng.next_double(), u2 = rng.next_double(), u3 = rng.next_double();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(2 * kPi * u2), x = a * std::cos(2 * kPi * u2);
  const double y = b * std::sin(2 * kPi * u3), z = b * std::cos(2 * kPi * u3);
  return {{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}}};
}

// Coefficients uniform in [−1, 1]: a generic, non-symmetric band-limited function.
inline std::vector<double> random_coefficients(Pcg32& rng, int order) {
  std::vector<double> c(sh_count(order));
  for (double& v : c) v = 2.0 * rng.next_double() - 1.0;
  return c;
}

inline double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace relight::test
