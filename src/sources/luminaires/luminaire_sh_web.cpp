// Exact-in-C, Gauss–Legendre-in-γ SH projection of a bilinear type-C web (Dobashi et al.
// 1995 §3.2 for a C-dependent distribution); the formulas are in
// luminaire_sh_web.h.
#include "sources/luminaires/luminaire_sh_web.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "math/legendre.h"
#include "math/sh.h"
#include "math/vec3.h"

namespace relight {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

// Per C cell k and m >= 1 the factors that turn the rise ΔI_k into its contribution to
// ∫ I cos(mC) dC (tc) and ∫ I sin(mC) dC (ts): S = 2 sin(mΔ/2)/(Δ m²), tc = −S sin(mC̄),
// ts = S cos(mC̄). Stored [k · order + m] (m = 0 unused). Angles by complex recurrence.
struct FourierTable {
  std::vector<double> tc, ts;
};

FourierTable fourier_table(const std::vector<double>& c_rad, int order) {
  const std::size_t cells = c_rad.size() - 1;
  FourierTable t;
  t.tc.assign(cells * order, 0.0);
  t.ts.assign(cells * order, 0.0);
  for (std::size_t k = 0; k < cells; ++k) {
    const double width = c_rad[k + 1] - c_rad[k];
    const double mid = 0.5 * (c_rad[k + 1] + c_rad[k]);
    const double ch = std::cos(0.5 * width), sh = std::sin(0.5 * width);
    const double cm = std::cos(mid), sm = std::sin(mid);
    double a_re = 1.0, a_im = 0.0;  // e^{i m Δ/2}
    double b_re = 1.0, b_im = 0.0;  // e^{i m C̄}
    for (int m = 1; m < order; ++m) {
      const double a_next = a_re * ch - a_im * sh;
      a_im = a_re * sh + a_im * ch;
      a_re = a_next;
      const double b_next = b_re * cm - b_im * sm;
      b_im = b_re * sm + b_im * cm;
      b_re = b_next;
      const double s = 2.0 * a_im / (width * m * m);
      t.tc[k * order + m] = -s * b_im;
      t.ts[k * order + m] = s * b_re;
    }
  }
  return t;
}

// Fourier integrals of every γ row: row j holds, at [j · (2·order)], F_0 = ∫ I dC, then
// A_m = ∫ I cos(mC) dC at 2m and B_m = ∫ I sin(mC) dC at 2m + 1 (m >= 1).
std::vector<double> row_fourier(const PhotometricWeb& web, const std::vector<double>& c_rad,
                                int order) {
  const std::size_t nc = c_rad.size(), ng = web.gamma_deg.size();
  const FourierTable t = fourier_table(c_rad, order);
  const std::size_t stride = 2 * static_cast<std::size_t>(order);
  std::vector<double> f(ng * stride, 0.0);
  for (std::size_t j = 0; j < ng; ++j) {
    double* row = &f[j * stride];
    double f0 = 0.0;
    for (std::size_t k = 0; k + 1 < nc; ++k) {
      const double v0 = web.at(k, j), v1 = web.at(k + 1, j);
      f0 += 0.5 * (v0 + v1) * (c_rad[k + 1] - c_rad[k]);
      const double rise = v1 - v0;
      if (rise == 0.0) continue;
      const double* tc = &t.tc[k * order];
      const double* ts = &t.ts[k * order];
      for (int m = 1; m < order; ++m) {
        row[2 * std::ptrdiff_t{m}] += rise * tc[m];
        row[2 * std::ptrdiff_t{m} + 1] += rise * ts[m];
      }
    }
    row[0] = f0;
    // Boundary term of the integration by parts: non-zero only when the plane at 360°
    // differs from the one at 0°.
    const double jump = web.at(nc - 1, j) - web.at(0, j);
    if (jump != 0.0) {
      for (int m = 1; m < order; ++m) row[2 * m + 1] -= jump / m;
    }
  }
  return f;
}

int gauss_nodes_per_cell(int order, double width_rad) {
  return 4 + static_cast<int>(std::ceil(0.5 * order * width_rad));
}

}  // namespace

std::vector<double> web_local_sh(const PhotometricWeb& web, int order) {
  return web_local_sh(web, order, 0);
}

std::vector<double> web_local_sh(const PhotometricWeb& web, int order, int q_extra) {
  if (order < 1) throw std::invalid_argument("web_local_sh: order must be >= 1");
  std::vector<double> c(sh_count(order), 0.0);
  const std::size_t nc = web.c_deg.size(), ng = web.gamma_deg.size();
  if (nc < 2 || ng < 2 || web.candela.size() != nc * ng) return c;

  std::vector<double> c_rad(nc), g_rad(ng);
  for (std::size_t k = 0; k < nc; ++k) c_rad[k] = radians(web.c_deg[k]);
  for (std::size_t j = 0; j < ng; ++j) g_rad[j] = radians(web.gamma_deg[j]);
  const std::vector<double> fourier = row_fourier(web, c_rad, order);
  const std::size_t stride = 2 * static_cast<std::size_t>(order);

  std::vector<GaussLegendre> rules;  // rules[q] built on first use
  std::vector<double> p(assoc_legendre_count(order));
  std::vector<double> f(stride);
  for (std::size_t j = 0; j + 1 < ng; ++j) {
    const double a = g_rad[j], b = g_rad[j + 1];
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    const int q = gauss_nodes_per_cell(order, b - a) + std::max(0, q_extra);
    if (static_cast<int>(rules.size()) <= q) rules.resize(q + 1);
    if (rules[q].nodes.empty()) rules[q] = gauss_legendre(q);
    const GaussLegendre& gl = rules[q];
    const double* f_lo = &fourier[j * stride];
    const double* f_hi = &fourier[(j + 1) * stride];
    for (int i = 0; i < q; ++i) {
      const double gamma = mid + half * gl.nodes[i];
      const double t = 0.5 * (1.0 + gl.nodes[i]);  // (γ − a)/(b − a)
      const double w = half * gl.weights[i] * std::sin(gamma);
      for (std::size_t s = 0; s < stride; ++s) f[s] = w * (f_lo[s] + t * (f_hi[s] - f_lo[s]));
      assoc_legendre_normalized(order, std::cos(gamma), p);
      for (int l = 0; l < order; ++l) {
        c[sh_index(l, 0)] += p[assoc_legendre_index(l, 0)] * f[0];
        for (int m = 1; m <= l; ++m) {
          const double pl = kSqrt2 * p[assoc_legendre_index(l, m)];
          c[sh_index(l, m)] += pl * f[2 * static_cast<std::size_t>(m)];
          // sin(mC) term, negated: y = −C90 in the right-handed frame.
          c[sh_index(l, -m)] -= pl * f[2 * m + 1];
        }
      }
    }
  }
  return c;
}

}  // namespace relight
