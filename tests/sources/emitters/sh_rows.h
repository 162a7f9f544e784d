// What the reconstruction tests share: comparing one point's row of reconstructed SH
// coefficients (RGB) with an expected vector, and weighted mixes of such vectors.
#pragma once

#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "math/rgb.h"

namespace relight::testing {

// out holds expected.size() coefficients per point; compares the row of `point`.
inline void expect_row(std::span<const Rgb> out, std::size_t point,
                       const std::vector<Rgb>& expected, double tolerance) {
  const std::size_t k = expected.size();
  for (std::size_t j = 0; j < k; ++j) {
    const Rgb got = out[point * k + j];
    EXPECT_NEAR(got.r, expected[j].r, tolerance) << "point " << point << " coefficient " << j;
    EXPECT_NEAR(got.g, expected[j].g, tolerance) << "point " << point << " coefficient " << j;
    EXPECT_NEAR(got.b, expected[j].b, tolerance) << "point " << point << " coefficient " << j;
  }
}

inline std::vector<Rgb> mix(const std::vector<Rgb>& a, double wa, const std::vector<Rgb>& b,
                            double wb) {
  std::vector<Rgb> m;
  for (std::size_t j = 0; j < a.size(); ++j) m.push_back(wa * a[j] + wb * b[j]);
  return m;
}

}  // namespace relight::testing
