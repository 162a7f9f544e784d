// The 2D non-standard Haar transform (math/haar.h) used by the per-face wavelet encoding of
// Yue et al. 2009 (Yue et al. 2009 §4.1.2): exact inverse, orthonormality (Parseval, which the
// run-time sparse dot product relies on), the documented basis supports and coefficient
// normalisation, and the RGB / multi-face variants.
#include "math/haar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "math/sampling.h"

namespace relight {
namespace {

std::vector<double> random_face(Pcg32& rng, int n) {
  std::vector<double> f(std::size_t(n) * n);
  for (double& v : f) v = rng.next_double();
  return f;
}

TEST(Haar, ForwardInverseRoundTripTo1e12) {
  Pcg32 rng(1, 2);
  for (int n : {1, 2, 4, 8, 32, 64}) {
    const std::vector<double> x = random_face(rng, n);
    std::vector<double> y = x, scratch(n);
    haar2d_forward(y, n, scratch);
    haar2d_inverse(y, n, scratch);
    double err = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) err = std::max(err, std::abs(x[k] - y[k]));
    EXPECT_LE(err, 1e-12) << n;
  }
}

TEST(Haar, ParsevalPreservesDotProductsTo1e10) {
  Pcg32 rng(3, 4);
  for (int n : {2, 8, 32}) {
    const std::vector<double> x = random_face(rng, n), y = random_face(rng, n);
    std::vector<double> hx = x, hy = y, scratch(n);
    haar2d_forward(hx, n, scratch);
    haar2d_forward(hy, n, scratch);
    double xy = 0, hxhy = 0, xx = 0, hxhx = 0;
    for (std::size_t k = 0; k < x.size(); ++k) {
      xy += x[k] * y[k];
      hxhy += hx[k] * hy[k];
      xx += x[k] * x[k];
      hxhx += hx[k] * hx[k];
    }
    EXPECT_NEAR(hxhy / xy, 1.0, 1e-10) << n;
    EXPECT_NEAR(hxhx / xx, 1.0, 1e-10) << n;
  }
}

// Inverse-transforming each unit coefficient gives the basis: orthonormal, ±1/S on S×S cells
// with S = haar2d_support, and every cell under exactly 1 + 3·log2 N of them.
TEST(Haar, BasisIsOrthonormalWithDocumentedSupports) {
  const int n = 8, nn = n * n, levels = 3;
  std::vector<std::vector<double>> basis(nn);
  std::vector<double> scratch(n);
  for (int k = 0; k < nn; ++k) {
    basis[k].assign(nn, 0.0);
    basis[k][k] = 1.0;
    haar2d_inverse(basis[k], n, scratch);
  }
  for (int k = 0; k < nn; ++k)
    for (int l = 0; l < nn; ++l) {
      double d = 0.0;
      for (int c = 0; c < nn; ++c) d += basis[k][c] * basis[l][c];
      EXPECT_NEAR(d, k == l ? 1.0 : 0.0, 1e-12) << k << " " << l;
    }
  std::vector<int> under(nn, 0);
  for (int k = 0; k < nn; ++k) {
    const int s = haar2d_support(n, k / n, k % n);
    int nonzero = 0;
    for (int c = 0; c < nn; ++c) {
      if (std::abs(basis[k][c]) < 1e-12) continue;
      EXPECT_NEAR(std::abs(basis[k][c]), 1.0 / s, 1e-12) << k;
      ++nonzero;
      ++under[c];
    }
    EXPECT_EQ(nonzero, s * s) << k;
  }
  for (int c = 0; c < nn; ++c) EXPECT_EQ(under[c], 1 + 3 * levels) << c;
  EXPECT_EQ(haar2d_support(n, 0, 0), 8);
  EXPECT_EQ(haar2d_support(n, 0, 1), 8);
  EXPECT_EQ(haar2d_support(n, 3, 2), 4);
  EXPECT_EQ(haar2d_support(n, 7, 0), 2);
}

TEST(Haar, ConstantFaceHasOnlyScalingCoefficientNTimesValue) {
  const int n = 16;
  std::vector<double> f(n * n, 0.25), scratch(n);
  haar2d_forward(f, n, scratch);
  EXPECT_NEAR(f[0], n * 0.25, 1e-13);
  for (int k = 1; k < n * n; ++k) EXPECT_NEAR(f[k], 0.0, 1e-13) << k;
}

TEST(Haar, RgbAndMultiFaceVariantsMatchScalarPerFace) {
  Pcg32 rng(5, 6);
  const int n = 8, nn = n * n;
  std::vector<double> r = random_face(rng, n), g = random_face(rng, n), b = random_face(rng, n);
  std::vector<Rgb> c(nn);
  for (int k = 0; k < nn; ++k) c[k] = {r[k], g[k], b[k]};
  std::vector<Rgb> rgb_scratch(n);
  haar2d_forward(c, n, rgb_scratch);
  std::vector<double> scratch(n);
  // Three faces transformed at once equal each transformed alone.
  std::vector<double> all = r;
  all.insert(all.end(), g.begin(), g.end());
  all.insert(all.end(), b.begin(), b.end());
  haar2d_forward_faces(all, n, scratch);
  haar2d_forward(r, n, scratch);
  haar2d_forward(g, n, scratch);
  haar2d_forward(b, n, scratch);
  for (int k = 0; k < nn; ++k) {
    EXPECT_DOUBLE_EQ(c[k].r, r[k]);
    EXPECT_DOUBLE_EQ(c[k].g, g[k]);
    EXPECT_DOUBLE_EQ(c[k].b, b[k]);
    EXPECT_DOUBLE_EQ(all[k], r[k]);
    EXPECT_DOUBLE_EQ(all[nn + k], g[k]);
    EXPECT_DOUBLE_EQ(all[2 * nn + k], b[k]);
  }
  haar2d_inverse_faces(all, n, scratch);
  haar2d_inverse(c, n, rgb_scratch);
  for (int k = 0; k < nn; ++k) {
    EXPECT_NEAR(all[k], c[k].r, 1e-14);
    EXPECT_NEAR(all[2 * nn + k], c[k].b, 1e-14);
  }
}

TEST(Haar, RejectsBadSizes) {
  std::vector<double> f(36), scratch(6);
  EXPECT_THROW(haar2d_forward(f, 6, scratch), std::invalid_argument);
  std::vector<double> g(64), small(4);
  EXPECT_THROW(haar2d_forward(g, 8, small), std::invalid_argument);
  std::vector<double> odd(65), s8(8);
  EXPECT_THROW(haar2d_forward_faces(odd, 8, s8), std::invalid_argument);
  EXPECT_TRUE(is_power_of_two(1) && is_power_of_two(32) && !is_power_of_two(0) &&
              !is_power_of_two(12));
}

}  // namespace
}  // namespace relight
