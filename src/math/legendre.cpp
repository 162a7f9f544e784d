// Legendre recurrences and Gauss–Legendre rule; see legendre.h for the formulas and sources.
#include "math/legendre.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "math/tabulated.h"
#include "math/vec3.h"

namespace relight {

double legendre(int l, double x) {
  assert(l >= 0);
  if (l == 0) return 1.0;
  double p_prev = 1.0, p = x;
  for (int k = 1; k < l; ++k) {
    const double p_next = ((2 * k + 1) * x * p - k * p_prev) / (k + 1);
    p_prev = p;
    p = p_next;
  }
  return p;
}

void legendre_all(double x, std::span<double> out) {
  if (out.empty()) return;
  out[0] = 1.0;
  if (out.size() == 1) return;
  out[1] = x;
  for (std::size_t k = 1; k + 1 < out.size(); ++k) {
    const double kd = static_cast<double>(k);
    out[k + 1] = ((2 * kd + 1) * x * out[k] - kd * out[k - 1]) / (kd + 1);
  }
}

void assoc_legendre_normalized(int order, double x, std::span<double> out) {
  assert(static_cast<int>(out.size()) >= assoc_legendre_count(order));
  if (order <= 0) return;
  const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
  double pmm = 1.0 / std::sqrt(4.0 * kPi);  // Pbar_0^0
  for (int m = 0; m < order; ++m) {
    if (m > 0) pmm *= std::sqrt((2.0 * m + 1.0) / (2.0 * m)) * s;
    out[assoc_legendre_index(m, m)] = pmm;
    if (m + 1 >= order) break;
    double p_prev = pmm;
    double p = std::sqrt(2.0 * m + 3.0) * x * pmm;
    out[assoc_legendre_index(m + 1, m)] = p;
    for (int l = m + 2; l < order; ++l) {
      const double l2 = double(l) * l, m2 = double(m) * m, lm1 = double(l - 1) * (l - 1);
      const double a = std::sqrt((4.0 * l2 - 1.0) / (l2 - m2));
      const double b = std::sqrt((lm1 - m2) / (4.0 * lm1 - 1.0));
      const double p_next = a * (x * p - b * p_prev);
      p_prev = p;
      p = p_next;
      out[assoc_legendre_index(l, m)] = p;
    }
  }
}

namespace {

GaussLegendre solve_gauss_legendre(int n) {
  assert(n >= 1);
  // P_n(x) and P_n'(x) = n (x P_n − P_{n−1}) / (x² − 1) (|x| < 1 at every iterate).
  const auto p_and_derivative = [n](double x, double& dp) {
    double p_prev = 1.0, p = x;
    for (int k = 1; k < n; ++k) {
      const double p_next = ((2 * k + 1) * x * p - k * p_prev) / (k + 1);
      p_prev = p;
      p = p_next;
    }
    dp = n * (x * p - p_prev) / (x * x - 1.0);
    return p;
  };
  GaussLegendre rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));  // i-th largest root, approximately
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      const double dx = p_and_derivative(x, dp) / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    p_and_derivative(x, dp);
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    rule.nodes[n - 1 - i] = x;
    rule.weights[n - 1 - i] = w;
    rule.nodes[i] = -x;
    rule.weights[i] = w;
  }
  if (n % 2 == 1) rule.nodes[n / 2] = 0.0;
  return rule;
}

}  // namespace

const GaussLegendre& gauss_legendre(int n) {
  return tabulated<GaussLegendre>(n, [](int k) { return solve_gauss_legendre(k); });
}

}  // namespace relight
