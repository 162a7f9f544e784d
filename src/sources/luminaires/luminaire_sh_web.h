// Full SH projection of a measured type-C web (IES / EULUMDAT) in the luminaire's own
// right-handed frame: the general case of Dobashi et al. 1995 §3.2, where the
// distribution depends on C as well as γ and the addition theorem (Eq. 7-10) no longer suffices; it
// is aimed afterwards by a general SH rotation, not projected again.
//
// What is projected is the web's own interpolant (light/photometric_web.h: bilinear in
// (C, γ), periodic in C, zero outside the measured γ range), so the l = 0 term reproduces
// PhotometricWeb::flux_lm to rounding. The quadrature follows the interpolant's structure
// instead of a generic sphere rule (which would converge slowly across the kinks at every
// measured angle and the jump at the end of the γ range):
//  * C: on each γ row the interpolant is piecewise linear and periodic in C, so its Fourier
//    integrals ∫ I(C) {cos, sin}(mC) dC are exact in closed form. Integrating by parts,
//    ∫ f e^{imC} dC = (f(2π)−f(0))/(im) + Σ_k ΔI_k · 2 sin(mΔC_k/2)/(ΔC_k m²) · i e^{im C̄_k}
//    (ΔI_k, ΔC_k, C̄_k: rise, width and midpoint of C cell k), which needs no small-angle
//    cancellation.
//  * γ: between two rows the interpolant is linear in γ, so the Fourier coefficients are too,
//    and c_lm = ∫ Pbar_l^m(cosγ) F_m(γ) sinγ dγ is a smooth integral per γ cell, done by
//    Gauss–Legendre in γ with q = 4 + ⌈order·Δγ/2⌉ nodes per cell (Δγ in radians). The
//    integrand per cell is a trigonometric polynomial of degree ≤ order in γ times a linear
//    factor; this q keeps the relative error below 1e-10 at orders up to 32 (checked
//    against q + 24 in tests/sources/luminaires/luminaire_sh_test.cpp, and against a brute-force
//    240 × 480 sphere rule for every C-dependent file in luminaire_sh_files_test.cpp).
// The flux (l = 0) of the shared IES/LDT files comes out within 1e-14 of flux_lm().
// Cost: (C cells)·order per row for the Fourier sums plus (γ nodes)·order² for the Legendre
// sums, cheaper than the generic product rule with ≥ 2·(γ resolution) nodes × uniform φ
// (measured: docs/decisions.md), and exact where that one is not.
#pragma once

#include <vector>

#include "light/photometric_web.h"

namespace relight {

// order² unwindowed SH coefficients (math/sh.h conventions) of the web's interpolant in the
// right-handed frame (x = C0, y = −C90, z = aim): the photometric-frame coefficients with
// every m < 0 coefficient negated (see sources/luminaires/luminaire_sh.h, "Handedness").
std::vector<double> web_local_sh(const PhotometricWeb& web, int order);

// Same with an explicit number of Gauss–Legendre nodes per γ cell (q_extra added to the
// default q above), for convergence checks.
std::vector<double> web_local_sh(const PhotometricWeb& web, int order, int q_extra);

}  // namespace relight
