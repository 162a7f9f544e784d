// Correlated colour temperature → linear Rec.709 chromaticity, for luminaire colours
// given as "cct_kelvin" in a lighting state. The Planckian locus is approximated by
// Kang et al. (2002), "Design of advanced color temperature control system for HDTV
// applications", J. Korean Physical Society 41(6) — cubic fits of x(T), y(T), valid for
// 1667–25000 K; xy → XYZ (Y = 1) → linear sRGB/Rec.709 primaries, D65 white (IEC
// 61966-2-1 matrix). Negative components (deep red or blue CCTs outside the gamut) are
// clipped and the result rescaled to luminance 1, as luminaire colours are.
#pragma once

#include "math/rgb.h"

namespace relight {

inline constexpr double kMinCctKelvin = 1667, kMaxCctKelvin = 25000;

// Precondition: kMinCctKelvin <= kelvin <= kMaxCctKelvin.
Rgb cct_to_rgb(double kelvin);

}  // namespace relight
