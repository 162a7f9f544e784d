// Angle-dependent transmittance of uncoated glazing; formulas in glazing.h.
#include "math/glazing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace relight {

namespace {

struct Slab {
  double t = 0, r = 0;
};

// The stack of `panes` panes of internal transmittance tau, one polarisation of interface
// reflectance r, the path in the glass 1/cos_t times the pane's.
double stack_transmittance(double r, double tau, double cos_t, int panes) {
  const double a = std::pow(tau, 1 / cos_t);
  const double denominator = 1 - r * r * a * a;
  const Slab pane{(1 - r) * (1 - r) * a / denominator,
                  r + (1 - r) * (1 - r) * r * a * a / denominator};
  Slab stack = pane;
  for (int k = 1; k < panes; ++k) {
    const double d = 1 - stack.r * pane.r;
    stack = {stack.t * pane.t / d, stack.r + stack.t * stack.t * pane.r / d};
  }
  return stack.t;
}

double transmittance(double cos_incidence, double tau, int panes) {
  const double c = std::min(cos_incidence, 1.0);
  if (!(c > 0)) return 0;
  const double n = kGlassRefractiveIndex;
  const double sin_t = std::sqrt(std::max(0.0, 1 - c * c)) / n;
  const double cos_t = std::sqrt(1 - sin_t * sin_t);
  const double rs = std::pow((c - n * cos_t) / (c + n * cos_t), 2);
  const double rp = std::pow((n * c - cos_t) / (n * c + cos_t), 2);
  return 0.5 *
         (stack_transmittance(rs, tau, cos_t, panes) + stack_transmittance(rp, tau, cos_t, panes));
}

}  // namespace

double max_glazing_transmittance(int panes) {
  return transmittance(1, 1, panes);
}

Glazing make_glazing(double visible_transmittance, int panes, bool diffusing) {
  if (panes < 1 || panes > kMaxPanes) {
    throw std::invalid_argument("glazing: panes must be 1, 2 or 3");
  }
  const double max = max_glazing_transmittance(panes);
  if (!(visible_transmittance > 0) || visible_transmittance > max) {
    throw std::invalid_argument("glazing: the visible transmittance of " + std::to_string(panes) +
                                " uncoated pane(s) lies in (0, " + std::to_string(max) + "]");
  }
  double lo = 0, hi = 1;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (transmittance(1, mid, panes) < visible_transmittance ? lo : hi) = mid;
  }
  return {visible_transmittance, panes, diffusing, 0.5 * (lo + hi)};
}

double glazing_transmittance(const Glazing& glazing, double cos_incidence) {
  return transmittance(cos_incidence, glazing.pane_internal_transmittance, glazing.panes);
}

}  // namespace relight
