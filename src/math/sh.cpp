// Real SH evaluation from Cartesian components and quadrature projection; conventions and
// sources in sh.h. The per-(l, m) recurrence factors are tabulated once for orders <= 64.
#include "math/sh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "math/legendre.h"

namespace relight {
namespace {

constexpr int kTableOrder = 64;

// Factors of Q_l^m = a_lm (z Q_{l−1}^m − b_lm Q_{l−2}^m), where Q_l^m = Pbar_l^m / sin^mθ.
struct Recurrence {
  double a, b;
};
Recurrence recurrence(int l, int m) {
  const double l2 = double(l) * l, m2 = double(m) * m, lm1 = double(l - 1) * (l - 1);
  return {std::sqrt((4.0 * l2 - 1.0) / (l2 - m2)), std::sqrt((lm1 - m2) / (4.0 * lm1 - 1.0))};
}

struct RecurrenceTable {
  std::vector<Recurrence> ab;              // [l * kTableOrder + m], l >= m + 2
  std::array<double, kTableOrder> diag{};  // sqrt((2m+1)/(2m)), m >= 1
  std::array<double, kTableOrder> sub{};   // sqrt(2m+3)
  RecurrenceTable() : ab(static_cast<std::size_t>(kTableOrder) * kTableOrder) {
    for (int m = 0; m < kTableOrder; ++m) {
      diag[m] = m == 0 ? 1.0 : std::sqrt((2.0 * m + 1.0) / (2.0 * m));
      sub[m] = std::sqrt(2.0 * m + 3.0);
      for (int l = m + 2; l < kTableOrder; ++l) ab[l * kTableOrder + m] = recurrence(l, m);
    }
  }
};
const RecurrenceTable& table() {
  static const RecurrenceTable t;
  return t;
}

// Calls emit(index, Y) for every (l, m) with l < order, m-major.
template <class Emit>
void for_each_sh(int order, Vec3 d, Emit&& emit) {
  if (order <= 0) return;
  const bool tabulated = order <= kTableOrder;
  const RecurrenceTable& t = table();
  constexpr double kSqrt2 = 1.41421356237309504880;
  double qmm = 0.5 / std::sqrt(kPi);  // Q_0^0 = 1 / sqrt(4π)
  double re = 1.0, im = 0.0;          // (x + iy)^m
  for (int m = 0; m < order; ++m) {
    if (m > 0) {
      qmm *= tabulated ? t.diag[m] : std::sqrt((2.0 * m + 1.0) / (2.0 * m));
      const double re_next = re * d.x - im * d.y;
      im = re * d.y + im * d.x;
      re = re_next;
    }
    const double cm = kSqrt2 * re, sm = kSqrt2 * im;
    const auto put = [&](int l, double q) {
      if (m == 0) {
        emit(sh_index(l, 0), q);
      } else {
        emit(sh_index(l, m), q * cm);
        emit(sh_index(l, -m), q * sm);
      }
    };
    put(m, qmm);
    if (m + 1 >= order) break;
    double q_prev = qmm;
    double q = (tabulated ? t.sub[m] : std::sqrt(2.0 * m + 3.0)) * d.z * qmm;
    put(m + 1, q);
    for (int l = m + 2; l < order; ++l) {
      const Recurrence r = tabulated ? t.ab[l * kTableOrder + m] : recurrence(l, m);
      const double q_next = r.a * (d.z * q - r.b * q_prev);
      q_prev = q;
      q = q_next;
      put(l, q);
    }
  }
}

}  // namespace

int sh_order_from_count(std::size_t count) {
  const int order = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
  assert(static_cast<std::size_t>(order) * order == count);
  return order;
}

void sh_eval(int order, Vec3 dir, std::span<double> out) {
  assert(static_cast<int>(out.size()) >= sh_count(order));
  for_each_sh(order, dir, [&](int i, double y) { out[i] = y; });
}

double sh_evaluate(std::span<const double> coeffs, Vec3 dir) {
  double sum = 0.0;
  for_each_sh(sh_order_from_count(coeffs.size()), dir,
              [&](int i, double y) { sum += coeffs[i] * y; });
  return sum;
}

Rgb sh_evaluate(std::span<const Rgb> coeffs, Vec3 dir) {
  Rgb sum;
  for_each_sh(sh_order_from_count(coeffs.size()), dir,
              [&](int i, double y) { sum += coeffs[i] * y; });
  return sum;
}

void sh_add_sample(Vec3 dir, double value, std::span<double> coeffs) {
  for_each_sh(sh_order_from_count(coeffs.size()), dir,
              [&](int i, double y) { coeffs[i] += value * y; });
}

void sh_add_sample(Vec3 dir, Rgb value, std::span<Rgb> coeffs) {
  for_each_sh(sh_order_from_count(coeffs.size()), dir,
              [&](int i, double y) { coeffs[i] += value * y; });
}

SphereQuadrature sphere_quadrature(int n_theta, int n_phi) {
  assert(n_theta >= 1 && n_phi >= 1);
  const GaussLegendre gl = gauss_legendre(n_theta);
  SphereQuadrature q;
  q.directions.reserve(static_cast<std::size_t>(n_theta) * n_phi);
  q.weights.reserve(static_cast<std::size_t>(n_theta) * n_phi);
  const double dphi = 2.0 * kPi / n_phi;
  for (int i = 0; i < n_theta; ++i) {
    const double z = gl.nodes[i];
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int k = 0; k < n_phi; ++k) {
      const double phi = (k + 0.5) * dphi;
      q.directions.push_back({r * std::cos(phi), r * std::sin(phi), z});
      q.weights.push_back(gl.weights[i] * dphi);
    }
  }
  return q;
}

SphereQuadrature sphere_quadrature_exact_to_degree(int degree) {
  assert(degree >= 0);
  return sphere_quadrature(degree / 2 + 1, degree + 1);
}

std::vector<double> sh_project(int order, const std::function<double(Vec3)>& f, int f_order) {
  if (f_order <= 0) f_order = order;
  return sh_project(order, f, sphere_quadrature_exact_to_degree(std::max(0, order + f_order - 2)));
}

std::vector<double> sh_project(int order, const std::function<double(Vec3)>& f,
                               const SphereQuadrature& rule) {
  std::vector<double> c(sh_count(order), 0.0);
  for (std::size_t k = 0; k < rule.directions.size(); ++k) {
    sh_add_sample(rule.directions[k], rule.weights[k] * f(rule.directions[k]), c);
  }
  return c;
}

std::vector<Rgb> sh_project_rgb(int order, const std::function<Rgb(Vec3)>& f,
                                const SphereQuadrature& rule) {
  std::vector<Rgb> c(sh_count(order));
  for (std::size_t k = 0; k < rule.directions.size(); ++k) {
    sh_add_sample(rule.directions[k], rule.weights[k] * f(rule.directions[k]), c);
  }
  return c;
}

}  // namespace relight
