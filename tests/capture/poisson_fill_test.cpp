// The Poisson fill (capture/poisson_fill.h): a harmonic map is reproduced exactly, the fill
// wraps across u = 0, and a map that is all hole is refused.
#include "capture/poisson_fill.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace relight {
namespace {

TEST(PoissonFill, AMapLinearInTheRowIsReproducedInsideAHoleTo1e9) {
  // f = 2 + 0.5 j is discretely harmonic along columns and constant along rows.
  const int w = 32, h = 16;
  std::vector<Rgb> texels(w * h);
  std::vector<std::uint8_t> hole(w * h, 0);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double f = 2 + 0.5 * j;
      texels[j * w + i] = {f, 2 * f, 3 * f};
      if (j >= 4 && j < 11 && i >= 10 && i < 20) {
        hole[j * w + i] = 1;
        texels[j * w + i] = {};
      }
    }
  }
  poisson_fill(w, h, texels, hole);
  for (int j = 4; j < 11; ++j) {
    for (int i = 10; i < 20; ++i) {
      const double f = 2 + 0.5 * j;
      EXPECT_NEAR(texels[j * w + i].r, f, 1e-6);
      EXPECT_NEAR(texels[j * w + i].g, 2 * f, 1e-6);
      EXPECT_NEAR(texels[j * w + i].b, 3 * f, 1e-6);
    }
  }
}

TEST(PoissonFill, AHoleAcrossTheSeamIsFilledFromBothSides) {
  // Left half 1, right half 3: a hole straddling u = 0 meets 1 on one side and 3 on the other,
  // so its middle (the seam) is near 2, not 1 (which no wrap would give).
  const int w = 64, h = 8;
  std::vector<Rgb> texels(w * h);
  std::vector<std::uint8_t> hole(w * h, 0);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const double v = i < w / 2 ? 1 : 3;
      texels[j * w + i] = {v, v, v};
      if (i < 4 || i >= w - 4) hole[j * w + i] = 1;
    }
  }
  poisson_fill(w, h, texels, hole);
  EXPECT_NEAR(texels[3 * w + 0].r, 2.0 - 1.0 / 9, 0.02);  // 1/9 of the way toward the 1 side
  EXPECT_NEAR(texels[3 * w + w - 1].r, 2.0 + 1.0 / 9, 0.02);
}

TEST(PoissonFill, AMapThatIsAllHoleIsRefused) {
  std::vector<Rgb> texels(8 * 4);
  std::vector<std::uint8_t> hole(8 * 4, 1);
  EXPECT_THROW(poisson_fill(8, 4, texels, hole), std::invalid_argument);
}

}  // namespace
}  // namespace relight
