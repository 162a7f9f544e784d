// The image circle (capture/image_circle.h) of synthetic fisheye photos: off-centre, with a
// dark lens-frame band inside the rim, cropped by the photo's edge.
#include "capture/image_circle.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.h"

namespace relight {
namespace {

// A lit disc (anti-aliased by 4 × 4 samples) with a band at 0.96–1 of the radius darkened to
// `band` of the value, on black.
Photo disc(int width, int height, double cx, double cy, double r, double band) {
  Photo photo{width, height, 8, std::vector<std::uint16_t>(3 * width * height, 0)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0;
      for (int s = 0; s < 16; ++s) {
        const double d = std::hypot(x + (s % 4 + 0.5) / 4 - cx, y + (s / 4 + 0.5) / 4 - cy);
        if (d <= r) sum += d > 0.96 * r ? band : 1;
      }
      const auto v = static_cast<std::uint16_t>(std::lround(180 * sum / 16));
      for (int c = 0; c < 3; ++c) photo.rgb[photo.offset(x, y) + c] = v;
    }
  }
  return photo;
}

void expect_found(int width, int height, ImageCircle truth) {
  const ImageCircle c =
      find_image_circle(disc(width, height, truth.cx, truth.cy, truth.radius, 0.3), "test");
  EXPECT_NEAR(c.cx, truth.cx, 0.5);
  EXPECT_NEAR(c.cy, truth.cy, 0.5);
  EXPECT_NEAR(c.radius, truth.radius, 0.5);
}

TEST(ImageCircle, AnOffCentreCircleWithADarkRimBandIsFoundWithinAHalfPixel) {
  expect_found(640, 480, {331.4, 228.7, 201.3});
}

TEST(ImageCircle, ACircleCroppedByThePhotosTopAndBottomIsStillFoundWithinAHalfPixel) {
  expect_found(640, 400, {322.2, 199.1, 230.6});
}

TEST(ImageCircle, ABlackPhotoIsAnInputErrorNamingIt) {
  const Photo photo{64, 48, 8, std::vector<std::uint16_t>(3 * 64 * 48, 0)};
  try {
    find_image_circle(photo, "dark.jpg");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("dark.jpg: no fisheye image circle found", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace relight
