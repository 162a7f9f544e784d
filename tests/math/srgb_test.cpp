// math/srgb.h against IEC 61966-2-1's curve: known values, continuity at the joints, and
// decode ∘ encode = identity.
#include "math/srgb.h"

#include <gtest/gtest.h>

namespace relight {
namespace {

TEST(Srgb, EncodeKnownValuesWithin1e6) {
  EXPECT_EQ(srgb_encode(0), 0.0);
  EXPECT_NEAR(srgb_encode(1), 1.0, 1e-12);
  EXPECT_NEAR(srgb_encode(0.5), 0.735357, 1e-6);
  EXPECT_NEAR(srgb_encode(0.18), 0.461356, 1e-6);
  EXPECT_NEAR(srgb_encode(0.0031308), 12.92 * 0.0031308, 1e-7);
  EXPECT_NEAR(srgb_encode(0.0031309), 12.92 * 0.0031309, 1e-6);  // continuous at the joint
}

TEST(Srgb, DecodeKnownValuesWithin1e6) {
  EXPECT_EQ(srgb_decode(0), 0.0);
  EXPECT_NEAR(srgb_decode(1), 1.0, 1e-12);
  EXPECT_NEAR(srgb_decode(128 / 255.0), 0.215861, 1e-6);
  EXPECT_NEAR(srgb_decode(0.04045), 0.04045 / 12.92, 1e-9);
  EXPECT_NEAR(srgb_decode(0.04046), 0.04046 / 12.92, 1e-6);  // continuous at the joint
}

TEST(Srgb, DecodeUndoesEncodeWithin1e12) {
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 1e-12) << x;
  }
}

}  // namespace
}  // namespace relight
