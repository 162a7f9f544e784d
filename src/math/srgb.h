// The sRGB transfer functions (IEC 61966-2-1:1999): the one place that turns 8-bit display
// and file colours into linear Rec.709 (math/rgb.h) and back. Decoding: c / 12.92 for
// c ≤ 0.04045, else ((c + 0.055) / 1.055)^2.4; encoding is its inverse, 12.92 x for
// x ≤ 0.0031308, else 1.055 x^(1/2.4) − 0.055. Pinned by tests/math/srgb_test.cpp.
#pragma once

#include <cmath>

namespace relight {

// Encoded value in [0, 1] → linear.
inline double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Linear value in [0, 1] → encoded (the OETF).
inline double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace relight
