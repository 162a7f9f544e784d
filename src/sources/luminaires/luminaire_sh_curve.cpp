// Incremental SH weights of an edited curve distribution (Dobashi et al. 1995 Eq. 19-21,
// aimed by Eq. 9-10); see luminaire_sh_curve.h.
#include "sources/luminaires/luminaire_sh_curve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "math/legendre.h"
#include "math/sh.h"
#include "math/sh_window.h"

namespace relight {
namespace {

// Width of the internal ramp that stands for the step to zero after the last control point.
constexpr double kStepGap = 1e-9;

// Adds (2l+1)/2 · Σ t_i value_i P_l(cosγ_i) sinγ_i over the composite-Simpson samples of
// [a, b] (`intervals` even) to w, value linear from va to vb.
void add_linear_simpson(double a, double b, double va, double vb, int intervals,
                        std::span<double> w, std::span<double> p) {
  const double h = (b - a) / intervals;
  for (int i = 0; i <= intervals; ++i) {
    const double g = i == intervals ? b : a + i * h;
    const double t = (i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double v = va + (vb - va) * (g - a) / (b - a);
    legendre_all(std::cos(g), p);
    const double s = t * h / 3.0 * v * std::sin(g);
    for (std::size_t l = 0; l < w.size(); ++l) w[l] += 0.5 * (2.0 * l + 1.0) * s * p[l];
  }
}

// The jump to zero after a last control point below π, on the Simpson panel [a, a + 2Δγ]
// holding it: the exact panel integral (Simpson on its linear pieces, 16 intervals each)
// minus what the panel's three uniform samples give. Zero when the curve ends at π.
std::vector<double> jump_panel_correction(const LegendreCurve& c, int point_count) {
  std::vector<double> w(c.max_degree + 1, 0.0), p(c.max_degree + 1);
  if (static_cast<int>(c.control_gamma.size()) == point_count) return w;
  const auto& g = c.control_gamma;
  const auto& v = c.control_value;
  const double h = kPi / c.intervals;
  const double last = g[point_count - 1];
  const int panel = std::min(static_cast<int>(std::floor(last / (2.0 * h))), c.intervals / 2 - 1);
  const double a = 2.0 * panel * h;
  // Exact: the control-point segments clipped to [a, last].
  for (int k = 0; k + 1 < point_count; ++k) {
    const double lo = std::max(a, g[k]), hi = std::min(last, g[k + 1]);
    if (!(hi > lo)) continue;
    const auto at = [&](double x) {
      return v[k] + (v[k + 1] - v[k]) * (x - g[k]) / (g[k + 1] - g[k]);
    };
    add_linear_simpson(lo, hi, at(lo), at(hi), 16, w, p);
  }
  // Minus the uniform samples of this panel, as LegendreCurve sees them.
  for (int i = 0; i < 3; ++i) {
    const double gi = kPi * (2 * panel + i) / c.intervals;  // as math/zonal.cpp samples
    const double t = i == 1 ? 4.0 : 1.0;
    legendre_all(std::cos(gi), p);
    const double s = t * h / 3.0 * curve_value(c, gi) * std::sin(gi);
    for (std::size_t l = 0; l < w.size(); ++l) w[l] -= 0.5 * (2.0 * l + 1.0) * s * p[l];
  }
  return w;
}

// Eq. 9-10 with the window: world_lm = 4π/(2l+1) · h_l w_l · Y_lm(aim).
void aim_legendre(std::span<const double> w, std::span<const double> correction,
                  const LuminaireShSettings& s, Vec3 aim, std::span<double> world) {
  const int order = static_cast<int>(w.size());
  if (static_cast<int>(world.size()) != sh_count(order))
    throw std::invalid_argument("curve SH: output must hold order² values");
  const double len = length(aim);
  if (!(len > 0) || !std::isfinite(len))
    throw std::invalid_argument("curve SH: aim must be a finite non-zero vector");
  sh_eval(order, aim / len, world);
  for (int l = 0; l < order; ++l) {
    const double scale = 4.0 * kPi / (2 * l + 1) *
                         sh_window_factor(s.window, order, l, s.window_param) *
                         (w[l] + correction[l]);
    for (int m = -l; m <= l; ++m) world[sh_index(l, m)] *= scale;
  }
}

}  // namespace

CurveProjector make_curve_projector(const CurveModel& model, const LuminaireShSettings& settings,
                                    int intervals) {
  if (settings.order < 1) throw std::invalid_argument("curve SH: order must be >= 1");
  const std::size_t n = model.gamma_rad.size();
  if (n < 2 || model.candela.size() != n)
    throw std::invalid_argument("curve SH: need >= 2 control points, one candela value each");
  if (model.gamma_rad.front() != 0.0)
    throw std::invalid_argument("curve SH: the first control point must be at γ = 0");
  std::vector<double> g = model.gamma_rad, v = model.candela;
  if (!(g.back() <= kPi)) throw std::invalid_argument("curve SH: control angles must be <= π");
  if (g.back() >= kPi - 2.0 * kStepGap) {
    g.back() = kPi;  // ends at π (to within the ramp width): nothing to append
  } else {
    const double last = g.back();
    g.push_back(last + kStepGap);
    v.push_back(0.0);
    g.push_back(kPi);
    v.push_back(0.0);
  }
  CurveProjector p;
  p.curve = make_legendre_curve(std::move(g), std::move(v), settings.order - 1, intervals,
                                IntegrationRule::kSimpson);
  p.point_count = static_cast<int>(n);
  p.settings = settings;
  p.step_correction = jump_panel_correction(p.curve, p.point_count);
  return p;
}

void move_curve_point(CurveProjector& p, int k, double gamma_rad, double candela) {
  const int n = p.point_count;
  if (k < 0 || k >= n) throw std::out_of_range("curve SH: no such control point");
  auto& g = p.curve.control_gamma;
  const bool ramp = static_cast<int>(g.size()) > n;  // internal points follow the last one
  if (k != n - 1 || !ramp) {
    move_control_point(p.curve, k, gamma_rad, candela);
    p.step_correction = jump_panel_correction(p.curve, n);
    return;
  }
  // The last point of a curve ending before π drags its ramp point along: two Eq. 21 moves,
  // ordered so that every intermediate curve stays strictly ascending.
  if (!(gamma_rad > g[k - 1] && gamma_rad < kPi - 2.0 * kStepGap))
    throw std::invalid_argument("curve SH: the last control point must stay in (previous, π)");
  if (gamma_rad > g[k]) {
    move_control_point(p.curve, n, gamma_rad + kStepGap, 0.0);
    move_control_point(p.curve, k, gamma_rad, candela);
  } else {
    move_control_point(p.curve, k, gamma_rad, candela);
    move_control_point(p.curve, n, gamma_rad + kStepGap, 0.0);
  }
  p.step_correction = jump_panel_correction(p.curve, n);
}

void move_curve_point(CurveProjector& p, int k, double candela) {
  if (k < 0 || k >= p.point_count) throw std::out_of_range("curve SH: no such control point");
  move_control_point(p.curve, k, p.curve.control_gamma[k], candela);
  p.step_correction = jump_panel_correction(p.curve, p.point_count);
}

CurveModel curve_model(const CurveProjector& p) {
  const auto n = static_cast<std::ptrdiff_t>(p.point_count);
  CurveModel m;
  m.gamma_rad.assign(p.curve.control_gamma.begin(), p.curve.control_gamma.begin() + n);
  m.candela.assign(p.curve.control_value.begin(), p.curve.control_value.begin() + n);
  return m;
}

void curve_world_sh(const CurveProjector& p, Vec3 aim, std::span<double> world) {
  aim_legendre(p.curve.weights, p.step_correction, p.settings, aim, world);
}

std::vector<double> curve_world_sh(const CurveProjector& p, Vec3 aim) {
  std::vector<double> world(sh_count(p.settings.order));
  curve_world_sh(p, aim, world);
  return world;
}

std::vector<double> recomputed_curve_world_sh(const CurveProjector& p, Vec3 aim) {
  const std::vector<double> w = recompute_legendre_weights(p.curve);
  std::vector<double> world(sh_count(p.settings.order));
  aim_legendre(w, jump_panel_correction(p.curve, p.point_count), p.settings, aim, world);
  return world;
}

}  // namespace relight
