#include "serve/half_float.h"

#include <bit>
#include <cmath>

namespace relight {

std::uint16_t float_to_half(float value) {
  if (std::isnan(value)) return 0;
  const auto f = std::bit_cast<std::uint32_t>(value);
  const auto sign = static_cast<std::uint16_t>((f >> 16) & 0x8000u);
  // 65520 and above would round to infinity.
  if (std::fabs(value) >= 65520.0f) return static_cast<std::uint16_t>(sign | 0x7BFFu);
  const int exponent = static_cast<int>((f >> 23) & 0xFFu) - 127 + 15;  // half's biased exponent
  std::uint32_t mantissa = f & 0x7FFFFFu;
  std::uint32_t half = 0, rest = 0, halfway = 0;
  if (exponent <= 0) {  // subnormal half: m · 2^−24
    if (exponent < -10) return sign;
    mantissa |= 0x800000u;
    const int shift = 14 - exponent;
    half = mantissa >> shift;
    rest = mantissa & ((1u << shift) - 1);
    halfway = 1u << (shift - 1);
  } else {
    half = (static_cast<std::uint32_t>(exponent) << 10) | (mantissa >> 13);
    rest = mantissa & 0x1FFFu;
    halfway = 0x1000u;
  }
  if (rest > halfway || (rest == halfway && (half & 1u))) ++half;  // a carry is still correct
  return static_cast<std::uint16_t>(sign | half);
}

float half_to_float(std::uint16_t half) {
  const float sign = (half & 0x8000u) ? -1.0f : 1.0f;
  const int exponent = (half >> 10) & 0x1F;
  const int mantissa = half & 0x3FF;
  if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
  if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
  return sign * std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
}

}  // namespace relight
