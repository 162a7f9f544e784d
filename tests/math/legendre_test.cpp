// Legendre polynomials, normalised associated Legendre functions and Gauss–Legendre rules
// against closed forms (math/legendre.h).
#include "math/legendre.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/vec3.h"

namespace relight {
namespace {

TEST(Legendre, PolynomialsMatchClosedFormsTo1e14) {
  for (double x : {-1.0, -0.7, -0.2, 0.0, 0.3, 0.55, 0.9, 1.0}) {
    const double x2 = x * x;
    EXPECT_NEAR(legendre(0, x), 1.0, 1e-14);
    EXPECT_NEAR(legendre(1, x), x, 1e-14);
    EXPECT_NEAR(legendre(2, x), 0.5 * (3 * x2 - 1), 1e-14);
    EXPECT_NEAR(legendre(3, x), 0.5 * (5 * x2 * x - 3 * x), 1e-14);
    EXPECT_NEAR(legendre(4, x), (35 * x2 * x2 - 30 * x2 + 3) / 8, 1e-14);
    EXPECT_NEAR(legendre(5, x), (63 * x2 * x2 * x - 70 * x2 * x + 15 * x) / 8, 1e-14);
  }
  // P_l(1) = 1 and P_l(−1) = (−1)^l for high degrees too.
  for (int l = 0; l < 64; ++l) {
    EXPECT_NEAR(legendre(l, 1.0), 1.0, 1e-12);
    EXPECT_NEAR(legendre(l, -1.0), l % 2 ? -1.0 : 1.0, 1e-12);
  }
}

TEST(Legendre, AllDegreesAtOnceMatchSingleDegreeTo1e13) {
  std::vector<double> p(41);
  for (double x : {-0.95, -0.3, 0.1, 0.77}) {
    legendre_all(x, p);
    for (int l = 0; l <= 40; ++l) EXPECT_NEAR(p[l], legendre(l, x), 1e-13) << l;
  }
}

TEST(Legendre, NormalizedAssociatedMatchClosedFormsTo1e13) {
  const int order = 41;
  std::vector<double> p(assoc_legendre_count(order));
  for (double x : {-0.9, -0.25, 0.0, 0.4, 0.99}) {
    assoc_legendre_normalized(order, x, p);
    const double s = std::sqrt(1 - x * x);
    const auto at = [&](int l, int m) { return p[assoc_legendre_index(l, m)]; };
    EXPECT_NEAR(at(0, 0), 1 / std::sqrt(4 * kPi), 1e-14);
    EXPECT_NEAR(at(1, 1), std::sqrt(3 / (8 * kPi)) * s, 1e-14);  // no Condon–Shortley phase
    EXPECT_NEAR(at(2, 1), std::sqrt(5 / (24 * kPi)) * 3 * x * s, 1e-14);
    EXPECT_NEAR(at(2, 2), std::sqrt(5 / (96 * kPi)) * 3 * s * s, 1e-14);
    EXPECT_NEAR(at(3, 3), std::sqrt(7 / (4 * kPi * 720)) * 15 * s * s * s, 1e-14);
    EXPECT_NEAR(at(3, 2), std::sqrt(7 / (4 * kPi * 120)) * 15 * x * s * s, 1e-14);
    for (int l = 0; l < order; ++l)
      EXPECT_NEAR(at(l, 0), std::sqrt((2 * l + 1) / (4 * kPi)) * legendre(l, x), 1e-13);
  }
}

TEST(Legendre, NormalizedAssociatedAreOrthonormalInXTo1e12) {
  // 2π ∫ Pbar_l^m Pbar_k^m dx = δ_lk (the φ integral of the real SH gives the 2π / π·2).
  const int order = 32;
  const GaussLegendre gl = gauss_legendre(order);
  std::vector<double> p(assoc_legendre_count(order));
  std::vector<double> gram(order * order * order, 0.0);  // [m][l][k]
  for (int i = 0; i < order; ++i) {
    assoc_legendre_normalized(order, gl.nodes[i], p);
    for (int m = 0; m < order; ++m)
      for (int l = m; l < order; ++l)
        for (int k = m; k < order; ++k)
          gram[(m * order + l) * order + k] += 2 * kPi * gl.weights[i] *
                                               p[assoc_legendre_index(l, m)] *
                                               p[assoc_legendre_index(k, m)];
  }
  for (int m = 0; m < order; ++m)
    for (int l = m; l < order; ++l)
      for (int k = m; k < order; ++k)
        EXPECT_NEAR(gram[(m * order + l) * order + k], l == k ? 1.0 : 0.0, 1e-12);
}

TEST(Legendre, GaussRuleIntegratesPolynomialsOfDegree2nMinus1Exactly) {
  for (int n = 1; n <= 40; ++n) {
    const GaussLegendre gl = gauss_legendre(n);
    ASSERT_EQ(static_cast<int>(gl.nodes.size()), n);
    for (int i = 1; i < n; ++i) EXPECT_LT(gl.nodes[i - 1], gl.nodes[i]);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += gl.weights[i] * std::pow(gl.nodes[i], k);
      const double exact = k % 2 ? 0.0 : 2.0 / (k + 1);
      EXPECT_NEAR(sum, exact, 1e-13) << "n=" << n << " k=" << k;
    }
  }
}

}  // namespace
}  // namespace relight
