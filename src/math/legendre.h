// Legendre polynomials, normalised associated Legendre functions and Gauss–Legendre nodes.
//
// P_l(x) by Bonnet's recurrence (l+1) P_{l+1} = (2l+1) x P_l − l P_{l−1}: the basis of the
// axisymmetric luminous intensity expansion I(γ) = Σ w_l P_l(cosγ) of Dobashi et al. 1995
// (Dobashi et al. 1995, Eq. 2) and of zonal harmonics (Y_l0 = sqrt((2l+1)/4π) P_l).
//
// The associated functions are the SH-normalised ones, without the Condon–Shortley phase:
//   Pbar_l^m(x) = sqrt((2l+1)/(4π) · (l−m)!/(l+m)!) · P_l^m(x),  P_l^m(x) = (1−x²)^{m/2} d^m
//   P_l/dx^m
// computed by the standard forward-column recurrences (sectoral Pbar_m^m from Pbar_{m−1}^{m−1},
// then upward in l for fixed m; see e.g. Holmes & Featherstone, J. Geodesy 76, 2002), which
// never form factorials and are stable to l in the hundreds (beyond, sin^mθ underflows near the
// poles). sh.cpp uses the same recurrences, divided by sin^mθ.
#pragma once

#include <span>
#include <vector>

namespace relight {

// P_l(x) for one degree l >= 0.
double legendre(int l, double x);

// P_0(x) .. P_{out.size()-1}(x) into out (no allocation).
void legendre_all(double x, std::span<double> out);

// Index of (l, m), 0 <= m <= l, in the triangular array filled by assoc_legendre_normalized.
constexpr int assoc_legendre_index(int l, int m) {
  return l * (l + 1) / 2 + m;
}
constexpr int assoc_legendre_count(int order) {
  return order * (order + 1) / 2;
}

// Pbar_l^m(x) for 0 <= m <= l < order (no Condon–Shortley phase; see above) into out, which
// must hold assoc_legendre_count(order) values. |x| <= 1.
void assoc_legendre_normalized(int order, double x, std::span<double> out);

// n-point Gauss–Legendre rule on [−1, 1]: exact for polynomials of degree <= 2n−1.
// Nodes ascending, symmetric (nodes[i] = −nodes[n − 1 − i] exactly). Newton iteration on P_n
// from the Tricomi initial guess, once per n for the life of the process (a sky is integrated
// with the same rules every hour of a year); safe to call from many threads.
struct GaussLegendre {
  std::vector<double> nodes;
  std::vector<double> weights;
};
const GaussLegendre& gauss_legendre(int n);

}  // namespace relight
