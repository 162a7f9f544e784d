// Tone mapping pins: the camera exposure convention (L_max = 1.2 · 2^EV100), automatic
// exposure putting the log-average luminance at the key 0.18, the highlight shoulder and
// the sRGB OETF.
#include "render/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace relight {
namespace {

TEST(ToneMapExposure, SaturationLuminanceIsCameraConvention) {
  EXPECT_DOUBLE_EQ(saturation_luminance(0), 1.2);
  EXPECT_DOUBLE_EQ(saturation_luminance(10), 1.2 * 1024);
  EXPECT_DOUBLE_EQ(exposure_scale(-1), 1 / 0.6);
  // One EV more halves the display value: higher EV100 is darker.
  EXPECT_DOUBLE_EQ(exposure_scale(5) / exposure_scale(6), 2.0);
}

TEST(ToneMapExposure, HalfOfSaturationIs188) {
  const Image image = make_image(1, 1, {0.6 * 128, 0.6 * 128, 0.6 * 128});
  const ToneMapped mapped = tone_map(image, 7.0);  // L_max = 1.2 · 128
  EXPECT_EQ(mapped.ev100, 7.0);
  EXPECT_NEAR(mapped.image.at(0, 0).g, 188, 1);
}

TEST(ToneMapAutoExposure, LogAverageExcludesUnlitAndNoSurfacePixels) {
  Image image = make_image(4, 1);
  image.at(0, 0) = {10, 10, 10};
  image.at(1, 0) = {1000, 1000, 1000};
  image.at(2, 0) = {0, 0, 0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  image.at(3, 0) = {nan, nan, nan};
  ASSERT_TRUE(log_average_luminance(image));
  EXPECT_NEAR(*log_average_luminance(image), 100.0, 1e-9);
  EXPECT_FALSE(log_average_luminance(make_image(2, 2)));
}

TEST(ToneMapAutoExposure, MapsLogAverageToKey) {
  Image image = make_image(3, 1);
  image.at(0, 0) = {10, 10, 10};
  image.at(1, 0) = {1000, 1000, 1000};
  image.at(2, 0) = {100, 100, 100};  // the log-average itself
  const double ev = auto_exposure_ev100(image);
  EXPECT_NEAR(ev, std::log2(100 / (1.2 * kAutoExposureKey)), 1e-12);
  EXPECT_NEAR(100 * exposure_scale(ev), kAutoExposureKey, 1e-12);

  const ToneMapped mapped = tone_map(image, std::nullopt);
  EXPECT_EQ(mapped.ev100, ev);
  // 0.18 → sRGB 0.4614 → 117.7
  EXPECT_NEAR(mapped.image.at(2, 0).r, 118, 1);
}

TEST(ToneMapAutoExposure, BlackImageUsesEvZero) {
  EXPECT_EQ(auto_exposure_ev100(make_image(2, 2)), 0.0);
}

TEST(ToneMapRolloff, IdentityBelowShoulderThenBoundedAndSmooth) {
  EXPECT_EQ(highlight_rolloff(0.3), 0.3);
  EXPECT_EQ(highlight_rolloff(kShoulderStart), kShoulderStart);
  const double h = 1e-6;
  const double slope = (highlight_rolloff(kShoulderStart + h) - kShoulderStart) / h;
  EXPECT_NEAR(slope, 1.0, 1e-5);
  EXPECT_NEAR(highlight_rolloff(1.0), 0.8, 1e-12);                    // L_max
  EXPECT_NEAR(highlight_rolloff(4.0), 0.6 + 0.4 * 8.5 / 9.5, 1e-12);  // 0.958
  double previous = 0;
  for (double x = 0.01; x < 1000; x *= 1.1) {
    const double y = highlight_rolloff(x);
    EXPECT_GT(y, previous);
    EXPECT_LT(y, 1.0);
    previous = y;
  }
  EXPECT_EQ(highlight_rolloff(std::numeric_limits<double>::infinity()), 1.0);
}

TEST(ToneMapSrgb, QuantizeRoundsAndClamps) {
  EXPECT_EQ(quantize_8bit(0.5), 128);
  EXPECT_EQ(quantize_8bit(-1), 0);
  EXPECT_EQ(quantize_8bit(2), 255);
  EXPECT_EQ(quantize_8bit(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(ToneMapImage, NegativeAndNanDisplayBlackVeryBrightDisplaysWhite) {
  Image image = make_image(3, 1);
  image.at(0, 0) = {-5, -5, -5};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  image.at(1, 0) = {nan, nan, nan};
  image.at(2, 0) = {1e6, 1e6, 1e6};
  const Image8 out = tone_map(image, 0.0).image;
  EXPECT_EQ(out.at(0, 0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(out.at(1, 0), (Rgb8{0, 0, 0}));
  EXPECT_EQ(out.at(2, 0), (Rgb8{255, 255, 255}));
}

}  // namespace
}  // namespace relight
