// IEEE 754 binary16 ("half") conversion for the studio's radiance frames
// (docs/studio-protocol.md, "Frame RLFR"): WebGL 2 takes half-float vertex attributes as
// they are, at half the bytes of float. Round to nearest, ties to even.
#pragma once

#include <cstdint>

namespace relight {

inline constexpr float kHalfMax = 65504.0f;

// Finite values beyond ±65504 clamp to ±65504 (never infinity); NaN becomes 0.
std::uint16_t float_to_half(float value);
float half_to_float(std::uint16_t half);

}  // namespace relight
