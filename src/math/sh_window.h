// Per-band windowing of truncated SH / Legendre expansions against Gibbs ringing.
//
// A window h_l multiplies every coefficient of band l (for zonal/Legendre expansions: w_l).
// Kinds, with N = order − 1 the highest degree kept:
//  * kNone      h_l = 1.
//  * kSigma     Lanczos' sigma factor, Dobashi et al. 1995 Eq. 12-13:
//               h_0 = 1, h_l = sin(πl/(N+1)) / (πl/(N+1)). It averages the truncated series
//               over one period of the first dropped degree N+1 (Hamming, Digital Filters 1977).
//  * kHanning   h_l = (1 + cos(πl/(N+1))) / 2: the Hann window of width N+1 as used for SH
//               in Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, §"Windowing".
//  * kGaussian  h_l = exp(−λ l(l+1)): the spherical heat kernel (diffusion for time λ);
//               smooth, never zero. param = λ.
//  * kLaplacian h_l = 1 / (1 + λ l²(l+1)²): the minimiser of ‖f − g‖² + λ‖∇²g‖² over the
//               band-limited g (the Laplacian penalty of Sloan, "Deringing Spherical
//               Harmonics", SIGGRAPH Asia 2017 Technical Briefs). param = λ.
// param is ignored by the kinds without one.
#pragma once

#include <span>
#include <vector>

#include "math/rgb.h"

namespace relight {

enum class ShWindow { kNone, kSigma, kHanning, kGaussian, kLaplacian };

// The sigma factor σ(N, l) of Eq. 13 (N = highest degree, 0 <= l <= N).
double sigma_factor(int highest_degree, int l);

// h_l for l < order.
double sh_window_factor(ShWindow kind, int order, int l, double param = 0.0);
void sh_window_factors(ShWindow kind, int order, std::span<double> out, double param = 0.0);
std::vector<double> sh_window_factors(ShWindow kind, int order, double param = 0.0);

// In place: SH vectors (order² values; every m of band l scaled by factors[l]) ...
void sh_apply_window(std::span<double> coeffs, std::span<const double> band_factors);
void sh_apply_window(std::span<Rgb> coeffs, std::span<const double> band_factors);
void sh_apply_window(ShWindow kind, std::span<double> coeffs, double param = 0.0);
void sh_apply_window(ShWindow kind, std::span<Rgb> coeffs, double param = 0.0);
// ... and per-degree Legendre weights or zonal coefficients (one value per band).
void zonal_apply_window(ShWindow kind, std::span<double> per_band, double param = 0.0);

}  // namespace relight
