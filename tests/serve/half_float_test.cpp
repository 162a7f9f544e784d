// serve/half_float.h: binary16 as WebGL reads it — exact for representable values, round to
// nearest even between them, clamped at ±65504 instead of infinity, NaN as 0.
#include <cmath>

#include <gtest/gtest.h>

#include "serve/half_float.h"

namespace relight {
namespace {

TEST(HalfFloat, RepresentableValuesRoundTripExactly) {
  for (const float v : {0.0f, 1.0f, -2.0f, 0.5f, 1024.0f, 65504.0f, 0.333251953125f,
                        6.103515625e-05f /* smallest normal */, 5.960464477539063e-08f /* sub */}) {
    EXPECT_EQ(half_to_float(float_to_half(v)), v) << v;
  }
  EXPECT_EQ(float_to_half(1.0f), 0x3C00);
  EXPECT_EQ(float_to_half(-2.0f), 0xC000);
  EXPECT_EQ(float_to_half(65504.0f), 0x7BFF);
}

TEST(HalfFloat, RoundsToNearestEven) {
  // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: ties go to the even mantissa (1).
  EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3C00);
  // 1 + 3·2^-11 lies halfway between 1 + 2^-10 (odd) and 1 + 2^-9 (even).
  EXPECT_EQ(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3C02);
  EXPECT_EQ(float_to_half(1.0f + 1.1f * std::ldexp(1.0f, -11)), 0x3C01);
  // Relative error of any normal value below 2^-11.
  for (float v = 1e-4f; v < 6e4f; v *= 1.37f) {
    EXPECT_LT(std::fabs(half_to_float(float_to_half(v)) - v) / v, std::ldexp(1.0f, -11)) << v;
  }
}

TEST(HalfFloat, ClampsInsteadOfInfinityAndZeroesNan) {
  EXPECT_EQ(half_to_float(float_to_half(1e6f)), 65504.0f);
  EXPECT_EQ(half_to_float(float_to_half(-1e30f)), -65504.0f);
  EXPECT_EQ(half_to_float(float_to_half(INFINITY)), 65504.0f);
  EXPECT_EQ(float_to_half(NAN), 0);
  EXPECT_EQ(float_to_half(1e-9f), 0);  // below half the smallest subnormal
}

}  // namespace
}  // namespace relight
