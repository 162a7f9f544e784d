// Window glazing as a transmittance that depends on the angle of incidence: uncoated panes of
// glass of refractive index n = 1.52 in air, each absorbing so that the whole glazing transmits
// `visible_transmittance` at normal incidence (the figure a glass maker gives).
//
// One pane, per polarisation (s, p), at incidence θ (cos θ = c) with the refraction angle
// sin θt = sin θ / n:
//   interface reflectance (Fresnel)  r_s = ((c − n·cos θt)/(c + n·cos θt))²,
//                                    r_p = ((n·c − cos θt)/(n·c + cos θt))²,
//   internal transmittance           a = τ^(1/cos θt)   (τ at normal incidence: the path in
//                                                         the glass grows as 1/cos θt),
//   the pane, every internal reflection summed:
//                                    T₁ = (1 − r)²·a / (1 − r²a²),
//                                    R₁ = r + (1 − r)²·r·a² / (1 − r²a²).
// Panes in series (air between them, every reflection between them summed; a stack of equal
// panes reflects alike from both sides):
//   T_{k+1} = T_k·T₁ / (1 − R_k·R₁),   R_{k+1} = R_k + T_k²·R₁ / (1 − R_k·R₁).
// The glazing's transmittance is the mean of the two polarisations' (natural light), and τ is
// solved (bisection) so that it equals visible_transmittance at θ = 0. Clear panes (τ = 1)
// transmit at most 0.9183 (one pane), 0.8490 (two) and 0.7894 (three) at normal incidence;
// a single pane of 0.88 keeps 0.656 of that at 75°. (Fresnel's equations and the slab sums:
// e.g. M. Born and E. Wolf, Principles of Optics, §1.5 and §7.6.)
// Tests: tests/math/glazing_test.cpp.
#pragma once

namespace relight {

inline constexpr double kGlassRefractiveIndex = 1.52;
inline constexpr int kMaxPanes = 3;

struct Glazing {
  double visible_transmittance = 1;  // at normal incidence, 0 < T ≤ the clear panes' maximum
  int panes = 1;                     // 1..3
  bool diffusing = false;            // transmits everything diffusely (the sun included)
  double pane_internal_transmittance = 1;  // τ, solved by make_glazing
  bool operator==(const Glazing&) const = default;
};

// The most `panes` clear panes transmit at normal incidence.
double max_glazing_transmittance(int panes);

// A glazing of `panes` panes transmitting `visible_transmittance` at normal incidence. Throws
// std::invalid_argument for panes outside 1..3 or a transmittance outside (0, the maximum].
Glazing make_glazing(double visible_transmittance, int panes, bool diffusing);

// Transmittance for light arriving at incidence cos θ = cos_incidence (0 at and beyond grazing).
double glazing_transmittance(const Glazing& glazing, double cos_incidence);

}  // namespace relight
