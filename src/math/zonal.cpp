// Zonal harmonics, Legendre weights by Simpson, and the incremental update of Dobashi et al.
// 1995 Eq. 21; see zonal.h for the equations.
#include "math/zonal.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "math/legendre.h"
#include "math/sh.h"

namespace relight {

void zonal_rotate(std::span<const double> zonal, Vec3 axis, std::span<double> out) {
  const int order = static_cast<int>(zonal.size());
  assert(static_cast<int>(out.size()) == sh_count(order));
  sh_eval(order, axis, out);
  for (int l = 0; l < order; ++l) {
    const double s = std::sqrt(4.0 * kPi / (2 * l + 1)) * zonal[l];
    for (int m = -l; m <= l; ++m) out[sh_index(l, m)] *= s;
  }
}

std::vector<double> zonal_rotate(std::span<const double> zonal, Vec3 axis) {
  std::vector<double> out(sh_count(static_cast<int>(zonal.size())));
  zonal_rotate(zonal, axis, out);
  return out;
}

std::vector<double> zonal_project(int order, const std::function<double(double)>& g, int n) {
  if (n <= 0) n = std::max(order, 1);
  const GaussLegendre gl = gauss_legendre(n);
  std::vector<double> z(order, 0.0), p(order);
  for (int i = 0; i < n; ++i) {
    legendre_all(gl.nodes[i], p);
    const double gw = 2.0 * kPi * gl.weights[i] * g(gl.nodes[i]);
    for (int l = 0; l < order; ++l) z[l] += gw * std::sqrt((2 * l + 1) / (4.0 * kPi)) * p[l];
  }
  return z;
}

void legendre_to_zonal(std::span<const double> w, std::span<double> z) {
  assert(w.size() == z.size());
  for (std::size_t l = 0; l < w.size(); ++l) z[l] = std::sqrt(4.0 * kPi / (2.0 * l + 1.0)) * w[l];
}

void zonal_to_legendre(std::span<const double> z, std::span<double> w) {
  assert(w.size() == z.size());
  for (std::size_t l = 0; l < z.size(); ++l) w[l] = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi)) * z[l];
}

double legendre_series(std::span<const double> w, double cos_gamma) {
  // Clenshaw would also do; the forward recurrence is stable for |x| <= 1.
  double sum = 0.0, p_prev = 0.0, p = 1.0;
  for (std::size_t l = 0; l < w.size(); ++l) {
    sum += w[l] * p;
    const double ld = static_cast<double>(l);
    const double p_next = ((2 * ld + 1) * cos_gamma * p - ld * p_prev) / (ld + 1);
    p_prev = p;
    p = p_next;
  }
  return sum;
}

double integration_weight(IntegrationRule rule, int i, int intervals) {
  assert(i >= 0 && i <= intervals);
  const double h = kPi / intervals;
  const bool end = i == 0 || i == intervals;
  if (rule == IntegrationRule::kTrapezoid) return end ? 0.5 * h : h;
  assert(intervals % 2 == 0);
  if (end) return h / 3.0;
  return (i % 2 == 1 ? 4.0 : 2.0) * h / 3.0;
}

namespace {

void check_intervals(int intervals, IntegrationRule rule) {
  if (intervals < 1) throw std::invalid_argument("Legendre weights: need at least one interval");
  if (rule == IntegrationRule::kSimpson && intervals % 2 != 0)
    throw std::invalid_argument("Legendre weights: Simpson's rule needs an even interval count");
}

double sample_gamma(int i, int intervals) {
  return kPi * i / intervals;
}

// table[l·(M+1) + i] = (2l+1)/2 · t_i Δγ · P_l(cosγ_i) sinγ_i.
std::vector<double> weight_table(int max_degree, int intervals, IntegrationRule rule) {
  check_intervals(intervals, rule);
  const int samples = intervals + 1;
  std::vector<double> table(static_cast<std::size_t>(max_degree + 1) * samples);
  std::vector<double> p(max_degree + 1);
  for (int i = 0; i < samples; ++i) {
    const double g = sample_gamma(i, intervals);
    legendre_all(std::cos(g), p);
    const double ts = integration_weight(rule, i, intervals) * std::sin(g);
    for (int l = 0; l <= max_degree; ++l) table[l * samples + i] = 0.5 * (2 * l + 1) * ts * p[l];
  }
  return table;
}

std::vector<double> apply_table(const std::vector<double>& table, int max_degree,
                                std::span<const double> samples) {
  const std::size_t n = samples.size();
  std::vector<double> w(max_degree + 1, 0.0);
  for (int l = 0; l <= max_degree; ++l) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += table[l * n + i] * samples[i];
    w[l] = sum;
  }
  return w;
}

double lerp_segment(double g0, double v0, double g1, double v1, double g) {
  return v0 + (v1 - v0) * ((g - g0) / (g1 - g0));
}

}  // namespace

std::vector<double> legendre_weights(std::span<const double> samples, int max_degree,
                                     IntegrationRule rule) {
  const int intervals = static_cast<int>(samples.size()) - 1;
  return apply_table(weight_table(max_degree, intervals, rule), max_degree, samples);
}

std::vector<double> legendre_weights(const std::function<double(double)>& intensity, int max_degree,
                                     int intervals, IntegrationRule rule) {
  std::vector<double> samples(intervals + 1);
  for (int i = 0; i <= intervals; ++i) samples[i] = intensity(sample_gamma(i, intervals));
  return legendre_weights(samples, max_degree, rule);
}

LegendreCurve make_legendre_curve(std::vector<double> control_gamma,
                                  std::vector<double> control_value, int max_degree, int intervals,
                                  IntegrationRule rule) {
  if (control_gamma.size() < 2 || control_gamma.size() != control_value.size())
    throw std::invalid_argument("Legendre curve: need >= 2 control points, one value each");
  if (control_gamma.front() != 0.0 || control_gamma.back() != kPi)
    throw std::invalid_argument("Legendre curve: control points must span γ = 0 to π");
  for (std::size_t k = 1; k < control_gamma.size(); ++k)
    if (!(control_gamma[k - 1] < control_gamma[k]))
      throw std::invalid_argument("Legendre curve: control angles must increase strictly");
  LegendreCurve c;
  c.control_gamma = std::move(control_gamma);
  c.control_value = std::move(control_value);
  c.max_degree = max_degree;
  c.intervals = intervals;
  c.rule = rule;
  c.table = weight_table(max_degree, intervals, rule);
  c.weights = recompute_legendre_weights(c);
  return c;
}

double curve_value(const LegendreCurve& c, double gamma) {
  const auto& g = c.control_gamma;
  const auto& v = c.control_value;
  if (gamma <= g.front()) return v.front();
  if (gamma >= g.back()) return v.back();
  // First control point with γ > gamma; the segment is [k−1, k].
  const std::size_t k = std::upper_bound(g.begin(), g.end(), gamma) - g.begin();
  return lerp_segment(g[k - 1], v[k - 1], g[k], v[k], gamma);
}

std::vector<double> recompute_legendre_weights(const LegendreCurve& c) {
  std::vector<double> samples(c.intervals + 1);
  for (int i = 0; i <= c.intervals; ++i) samples[i] = curve_value(c, sample_gamma(i, c.intervals));
  return apply_table(c.table, c.max_degree, samples);
}

int move_control_point(LegendreCurve& c, int k, double new_gamma, double new_value) {
  const int n = static_cast<int>(c.control_gamma.size());
  if (k < 0 || k >= n) throw std::out_of_range("Legendre curve: no such control point");
  auto& g = c.control_gamma;
  auto& v = c.control_value;
  if (k == 0) new_gamma = 0.0;
  if (k == n - 1) new_gamma = kPi;
  const double lo = k > 0 ? g[k - 1] : 0.0;
  const double hi = k < n - 1 ? g[k + 1] : kPi;
  if (!(lo < new_gamma && new_gamma < hi) && k != 0 && k != n - 1)
    throw std::invalid_argument("Legendre curve: a control point must stay between its neighbours");

  // I on [lo, hi] through control points k−1, k, k+1 (only these segments change).
  const auto local = [&](double gk, double vk, double gamma) {
    if (gamma < gk) return lerp_segment(g[k - 1], v[k - 1], gk, vk, gamma);
    if (gamma > gk) return lerp_segment(gk, vk, g[k + 1], v[k + 1], gamma);
    return vk;
  };

  const int m_int = c.intervals;
  const int samples = m_int + 1;
  const double h = kPi / m_int;
  const int i_begin = k == 0 ? 0 : std::max(0, static_cast<int>(std::floor(lo / h)));
  const int i_end = k == n - 1 ? m_int : std::min(m_int, static_cast<int>(std::ceil(hi / h)));
  // Samples on [lo, hi] are visited; those at the neighbours themselves (up to rounding of
  // γ_i) change by rounding only and are not counted as touched.
  const double tol = 1e-9 * h;
  int touched = 0;
  for (int i = i_begin; i <= i_end; ++i) {
    const double gamma = sample_gamma(i, m_int);
    if (gamma < lo - tol || gamma > hi + tol) continue;
    const bool inside = (gamma > lo + tol || (k == 0 && i == 0)) &&
                        (gamma < hi - tol || (k == n - 1 && i == m_int));
    touched += inside ? 1 : 0;
    const double gamma_c = std::clamp(gamma, lo, hi);
    const double delta = local(new_gamma, new_value, gamma_c) - local(g[k], v[k], gamma_c);
    if (delta == 0.0) continue;
    for (int l = 0; l <= c.max_degree; ++l) c.weights[l] += c.table[l * samples + i] * delta;
  }
  g[k] = new_gamma;
  v[k] = new_value;
  return touched;
}

int move_control_point(LegendreCurve& c, int k, double new_value) {
  // at(): k is checked before it is read (ASan found the read past the end for a bad k).
  return move_control_point(c, k, c.control_gamma.at(static_cast<std::size_t>(k)), new_value);
}

}  // namespace relight
