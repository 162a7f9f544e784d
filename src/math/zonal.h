// Zonal harmonics and Legendre expansions of axisymmetric intensity distributions.
//
// Dobashi, Kaneda, Nakatani, Yamashita, Nishita, "A Quick Rendering Method Using Basis
// Functions for Interactive Lighting Design", CGF 1995 (Dobashi et al. 1995):
//  * Eq. 2-3: I(γ) = Σ_l w_l P_l(cosγ), w_l = (2l+1)/2 ∫_0^π I(γ) P_l(cosγ) sinγ dγ.
//  * Eq. 19: the integral discretised on M+1 equally spaced samples γ_i = iπ/M,
//    w_l = (2l+1)/2 Σ_i t_i I(γ_i) f_l(γ_i) Δγ with f_l(γ) = P_l(cosγ) sinγ (Eq. 20).
//    The paper calls it Simpson's formula but prints the trapezoidal weights t = ½,1,…,1,½.
//    We implement composite Simpson (t = ⅓,⁴⁄₃,⅔,…,⁴⁄₃,⅓; M even) by default, and the
//    printed trapezoidal rule as an option.
//  * Eq. 21: moving one control point of the piecewise-linear curve changes I only on the
//    two segments next to it, so only the samples there change and
//    w_l += (2l+1)/2 Σ_{touched i} t_i ΔI(γ_i) f_l(γ_i) Δγ. The paper assumes one control point
//    per sample (then exactly one term changes); here control points are arbitrary, may also
//    move in γ, and the update touches exactly the samples strictly between the neighbours.
//  * Eq. 7-10 (addition theorem): aiming along a unit axis a gives the SH coefficients
//    f_lm = 4π/(2l+1) w_l Y_lm(a) = sqrt(4π/(2l+1)) z_l Y_lm(a), where z_l = sqrt(4π/(2l+1)) w_l
//    is the zonal coefficient (Y_l0 = sqrt((2l+1)/4π) P_l). SH conventions: math/sh.h.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

// ---- Zonal harmonics ----------------------------------------------------------------------

// f_lm = sqrt(4π/(2l+1)) z_l Y_lm(axis) for l < zonal.size(); out.size() == zonal.size()².
// The result is the SH projection of the axisymmetric function about `axis` whose
// coefficients about +z are z_l. No allocation.
void zonal_rotate(std::span<const double> zonal, Vec3 axis, std::span<double> out);
std::vector<double> zonal_rotate(std::span<const double> zonal, Vec3 axis);

// z_l = 2π ∫_{−1}^{1} g(x) Y_l0(x) dx for l < order, g given as a function of x = cosγ, by
// n-point Gauss–Legendre (n = 0: n = order, exact when g is a polynomial of degree < order).
std::vector<double> zonal_project(int order, const std::function<double(double)>& g, int n = 0);

// ---- Legendre weights <-> zonal coefficients ----------------------------------------------

// z_l = sqrt(4π/(2l+1)) w_l and back. out.size() == in.size(); in place allowed.
void legendre_to_zonal(std::span<const double> w, std::span<double> z);
void zonal_to_legendre(std::span<const double> z, std::span<double> w);
// Σ_l w_l P_l(cosγ).
double legendre_series(std::span<const double> w, double cos_gamma);

// ---- Legendre weights of a sampled distribution (Eq. 3, 19) -------------------------------

enum class IntegrationRule {
  kSimpson,    // composite Simpson, intervals even
  kTrapezoid,  // the weights printed in the paper's Eq. 19
};

// t_i·Δγ for sample i of `intervals` equal intervals on [0, π].
double integration_weight(IntegrationRule rule, int i, int intervals);

// w_0..w_max_degree from samples[i] = I(iπ/M), i = 0..M (M = samples.size() − 1).
// Throws std::invalid_argument when M < 1, or M is odd with Simpson's rule.
std::vector<double> legendre_weights(std::span<const double> samples, int max_degree,
                                     IntegrationRule rule = IntegrationRule::kSimpson);
// Same, sampling I(γ) at M + 1 points.
std::vector<double> legendre_weights(const std::function<double(double)>& intensity, int max_degree,
                                     int intervals,
                                     IntegrationRule rule = IntegrationRule::kSimpson);

// ---- Interactive editing of a piecewise-linear distribution (Eq. 21) ----------------------

struct LegendreCurve {
  // Control points, γ strictly increasing from 0 to π; I linear in γ between them.
  std::vector<double> control_gamma;
  std::vector<double> control_value;
  int max_degree = 0;  // N
  int intervals = 0;   // M: samples γ_i = iπ/M, i = 0..M
  IntegrationRule rule = IntegrationRule::kSimpson;
  // table[l·(M+1) + i] = (2l+1)/2 · t_i Δγ · P_l(cosγ_i) sinγ_i (the paper's stored f table
  // with the constant factors folded in), so w_l = Σ_i table[l][i] I(γ_i).
  std::vector<double> table;
  std::vector<double> weights;  // w_0..w_N, kept current by move_control_point
};

// Builds the table and the weights by full summation. Throws std::invalid_argument for bad
// control points (fewer than 2, not strictly increasing from 0 to π) or interval counts.
LegendreCurve make_legendre_curve(std::vector<double> control_gamma,
                                  std::vector<double> control_value, int max_degree, int intervals,
                                  IntegrationRule rule = IntegrationRule::kSimpson);

// The piecewise-linear I(γ) of the control points.
double curve_value(const LegendreCurve& curve, double gamma);

// Eq. 21: set control point k to (new_gamma, new_value) and update the weights by the change
// at the touched samples only. new_gamma must stay strictly between the neighbours'; the end
// points keep γ = 0 and γ = π (new_gamma is ignored for them). Returns the number of samples
// touched. Throws std::out_of_range / std::invalid_argument for a bad k / new_gamma.
int move_control_point(LegendreCurve& curve, int k, double new_gamma, double new_value);
int move_control_point(LegendreCurve& curve, int k, double new_value);

// Full Eq. 19 summation from the current control points (what the increments must equal).
std::vector<double> recompute_legendre_weights(const LegendreCurve& curve);

}  // namespace relight
