// SH windows (sigma factor of Dobashi et al. 1995 Eq. 13 and alternatives); see sh_window.h.
#include "math/sh_window.h"

#include <cassert>
#include <cmath>

#include "math/sh.h"
#include "math/vec3.h"

namespace relight {

double sigma_factor(int highest_degree, int l) {
  assert(l >= 0 && highest_degree >= 0);
  if (l == 0) return 1.0;
  const double x = kPi * l / (highest_degree + 1);
  return std::sin(x) / x;
}

double sh_window_factor(ShWindow kind, int order, int l, double param) {
  assert(order >= 1 && l >= 0);
  const double ld = l;
  switch (kind) {
    case ShWindow::kNone:
      return 1.0;
    case ShWindow::kSigma:
      return sigma_factor(order - 1, l);
    case ShWindow::kHanning:
      return 0.5 * (1.0 + std::cos(kPi * ld / order));
    case ShWindow::kGaussian:
      return std::exp(-param * ld * (ld + 1.0));
    case ShWindow::kLaplacian:
      return 1.0 / (1.0 + param * ld * ld * (ld + 1.0) * (ld + 1.0));
  }
  return 1.0;
}

void sh_window_factors(ShWindow kind, int order, std::span<double> out, double param) {
  assert(static_cast<int>(out.size()) >= order);
  for (int l = 0; l < order; ++l) out[l] = sh_window_factor(kind, order, l, param);
}

std::vector<double> sh_window_factors(ShWindow kind, int order, double param) {
  std::vector<double> h(order);
  sh_window_factors(kind, order, h, param);
  return h;
}

namespace {
template <class T>
void apply(std::span<T> coeffs, std::span<const double> h) {
  const int order = sh_order_from_count(coeffs.size());
  assert(static_cast<int>(h.size()) >= order);
  for (int l = 0; l < order; ++l)
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) coeffs[i] *= h[l];
}

template <class T>
void apply_kind(ShWindow kind, std::span<T> coeffs, double param) {
  const int order = sh_order_from_count(coeffs.size());
  for (int l = 0; l < order; ++l) {
    const double h = sh_window_factor(kind, order, l, param);
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) coeffs[i] *= h;
  }
}
}  // namespace

void sh_apply_window(std::span<double> coeffs, std::span<const double> h) {
  apply(coeffs, h);
}
void sh_apply_window(std::span<Rgb> coeffs, std::span<const double> h) {
  apply(coeffs, h);
}
void sh_apply_window(ShWindow kind, std::span<double> c, double p) {
  apply_kind(kind, c, p);
}
void sh_apply_window(ShWindow kind, std::span<Rgb> c, double p) {
  apply_kind(kind, c, p);
}

void zonal_apply_window(ShWindow kind, std::span<double> per_band, double param) {
  const int order = static_cast<int>(per_band.size());
  for (int l = 0; l < order; ++l) per_band[l] *= sh_window_factor(kind, order, l, param);
}

}  // namespace relight
