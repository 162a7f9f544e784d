// False colour pins: MIN and MAX take the ramp's end colours, log scales put the
// geometric mean mid-ramp, automatic ranges round to nice numbers, ticks stay readable,
// no-surface pixels are neutral, --range parses strictly, and the legend has the
// documented size and actually draws its labels.
#include "render/false_color.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/input_error.h"
#include "render/false_color_legend.h"

namespace relight {
namespace {

Image grey_row(std::initializer_list<double> values) {
  Image image = make_image(static_cast<int>(values.size()), 1);
  int x = 0;
  for (const double v : values) image.at(x++, 0) = {v, v, v};
  return image;
}

FalseColor request(std::optional<double> min, std::optional<double> max,
                   ScaleKind scale = ScaleKind::kAuto) {
  FalseColor fc;
  fc.quantity = Quantity::kIlluminance;
  fc.min = min;
  fc.max = max;
  fc.scale = scale;
  return fc;
}

TEST(FalseColorRamp, EndsAreFirstAndLastControlPoints) {
  EXPECT_EQ(ramp_color(0), kFalseColorRamp.front());
  EXPECT_EQ(ramp_color(1), kFalseColorRamp.back());
  EXPECT_EQ(ramp_color(-3), kFalseColorRamp.front());
  EXPECT_EQ(ramp_color(7), kFalseColorRamp.back());
  EXPECT_EQ(ramp_color(0.5), kFalseColorRamp[3]);
  EXPECT_EQ(ramp_color(std::numeric_limits<double>::quiet_NaN()), kNoSurfaceColor);
  for (const Rgb8 c : kFalseColorRamp) EXPECT_NE(c, kNoSurfaceColor);
}

TEST(FalseColorImage, MinMapsToFirstColourAndMaxToLast) {
  const Image image = grey_row({10, 1000, 5, 5000});
  const FalseColorImage out = render_false_color(image, request(10, 1000));
  EXPECT_EQ(out.scale.min, 10);
  EXPECT_EQ(out.scale.max, 1000);
  EXPECT_EQ(out.image.at(0, 0), kFalseColorRamp.front());
  EXPECT_EQ(out.image.at(1, 0), kFalseColorRamp.back());
  EXPECT_EQ(out.image.at(2, 0), kFalseColorRamp.front());  // below MIN
  EXPECT_EQ(out.image.at(3, 0), kFalseColorRamp.back());   // above MAX
}

TEST(FalseColorImage, LogScalePutsGeometricMeanMidRamp) {
  const Image image = grey_row({10, 100, 1000});
  const FalseColorScale scale = resolve_scale(image, request(10, 1000));
  EXPECT_TRUE(scale.logarithmic);  // MAX / MIN = 100 > 20
  EXPECT_NEAR(scale_position(scale, std::sqrt(10.0 * 1000.0)), 0.5, 1e-12);
  EXPECT_EQ(false_color_pixels(image, scale).at(1, 0), kFalseColorRamp[3]);
}

TEST(FalseColorImage, LinearScaleWhenRangeIsNarrow) {
  const Image image = grey_row({100, 300, 500});
  const FalseColorScale scale = resolve_scale(image, request(100, 500));
  EXPECT_FALSE(scale.logarithmic);  // MAX / MIN = 5
  EXPECT_NEAR(scale_position(scale, 300), 0.5, 1e-12);
  EXPECT_EQ(false_color_pixels(image, scale).at(1, 0), kFalseColorRamp[3]);
}

TEST(FalseColorImage, ExplicitScaleOverridesTheRatioRule) {
  const Image image = grey_row({1, 2});
  EXPECT_FALSE(resolve_scale(image, request(10, 1000, ScaleKind::kLinear)).logarithmic);
  EXPECT_TRUE(resolve_scale(image, request(100, 500, ScaleKind::kLogarithmic)).logarithmic);
  EXPECT_THROW(resolve_scale(image, request(0, 500, ScaleKind::kLogarithmic)), InputError);
}

TEST(FalseColorImage, NoSurfacePixelsAreNeutral) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Image image = grey_row({10, 20});
  image.at(1, 0).g = nan;
  const FalseColorImage out = render_false_color(image, request(1, 100));
  EXPECT_EQ(out.image.at(1, 0), kNoSurfaceColor);
}

TEST(FalseColorScale, AutomaticLogRangeRoundsOutToNiceNumbers) {
  Image image = make_image(1000, 1);
  for (int x = 0; x < 1000; ++x) {
    const double v = 13 * std::pow(870.0 / 13, x / 999.0);
    image.at(x, 0) = {v, v, v};
  }
  const FalseColorScale scale = resolve_scale(image, request(std::nullopt, std::nullopt));
  EXPECT_TRUE(scale.logarithmic);
  EXPECT_DOUBLE_EQ(scale.min, 10);
  EXPECT_DOUBLE_EQ(scale.max, 1000);
}

TEST(FalseColorScale, AutomaticRangeIgnoresOutlierPercent) {
  Image image = make_image(1000, 1, {200, 200, 200});
  for (int x = 0; x < 1000; ++x) image.at(x, 0) = Rgb{1, 1, 1} * (120 + 360 * x / 999.0);
  image.at(0, 0) = {1e7, 1e7, 1e7};  // a lamp
  image.at(1, 0) = {1e-3, 1e-3, 1e-3};
  const FalseColorScale scale = resolve_scale(image, request(std::nullopt, std::nullopt));
  EXPECT_FALSE(scale.logarithmic);
  EXPECT_DOUBLE_EQ(scale.min, 100);
  EXPECT_DOUBLE_EQ(scale.max, 500);
}

TEST(FalseColorScale, OneGivenEndKeepsTheOtherAutomatic) {
  const Image image = grey_row({1.5, 40, 700});
  const FalseColorScale low = resolve_scale(image, request(1, std::nullopt));
  EXPECT_EQ(low.min, 1);
  EXPECT_TRUE(low.logarithmic);
  EXPECT_DOUBLE_EQ(low.max, 1000);  // 700 rounded up to 1, 2, 5 × 10^k
  const FalseColorScale high = resolve_scale(image, request(std::nullopt, 50));
  EXPECT_EQ(high.max, 50);
  EXPECT_TRUE(high.logarithmic);
  EXPECT_DOUBLE_EQ(high.min, 1);  // 1.5 rounded down
}

TEST(FalseColorScale, DegenerateDataStillGivesARange) {
  const FalseColorScale flat = resolve_scale(make_image(3, 3, {50, 50, 50}), request({}, {}));
  EXPECT_EQ(flat.min, 0);
  EXPECT_DOUBLE_EQ(flat.max, 100);
  const FalseColorScale dark = resolve_scale(make_image(3, 3), request({}, {}));
  EXPECT_EQ(dark.min, 0);
  EXPECT_EQ(dark.max, 1);
}

TEST(FalseColorScale, TicksAreFiveToEightNiceValues) {
  const std::vector<double> log_2decades = scale_ticks({10, 1000, true});
  EXPECT_EQ(log_2decades, (std::vector<double>{10, 20, 50, 100, 200, 500, 1000}));
  const std::vector<double> log_4decades = scale_ticks({1, 10000, true});
  EXPECT_EQ(log_4decades, (std::vector<double>{1, 10, 100, 1000, 10000}));
  const std::vector<double> log_3decades = scale_ticks({0.5, 1000, true});
  EXPECT_EQ(log_3decades.size(), 7u);  // 1, 3, 10, 30, 100, 300, 1000
  EXPECT_EQ(scale_ticks({0, 500, false}), (std::vector<double>{0, 100, 200, 300, 400, 500}));
  EXPECT_EQ(scale_ticks({0, 1, false}).size(), 6u);  // step 0.2
  for (const FalseColorScale s : {FalseColorScale{2, 5000, true}, FalseColorScale{0.01, 1e5, true},
                                  FalseColorScale{3, 9, true}, FalseColorScale{0, 750, false},
                                  FalseColorScale{420, 610, false}}) {
    const std::size_t n = scale_ticks(s).size();
    EXPECT_GE(n, 4u) << s.min << ":" << s.max;
    EXPECT_LE(n, 8u) << s.min << ":" << s.max;
  }
}

TEST(FalseColorScale, TickLabelsAreShort) {
  EXPECT_EQ(format_tick(0), "0");
  EXPECT_EQ(format_tick(0.5), "0.5");
  EXPECT_EQ(format_tick(3 * 0.1), "0.3");
  EXPECT_EQ(format_tick(250), "250");
  EXPECT_EQ(format_tick(20000), "20000");
  EXPECT_EQ(format_tick(1.5e6), "1.5e6");
  EXPECT_EQ(format_tick(2e-4), "2e-4");
}

TEST(FalseColorScale, NiceNumbers) {
  EXPECT_DOUBLE_EQ(nice_floor_125(13), 10);
  EXPECT_DOUBLE_EQ(nice_floor_125(0.37), 0.2);
  EXPECT_DOUBLE_EQ(nice_floor_125(500), 500);
  EXPECT_DOUBLE_EQ(nice_ceil_125(870), 1000);
  EXPECT_DOUBLE_EQ(nice_ceil_125(0.0123), 0.02);
  EXPECT_DOUBLE_EQ(nice_ceil_125(200), 200);
}

TEST(FalseColorRange, ParsesMinMaxAndOpenEnds) {
  const RangeArgument both = parse_range("10:1000");
  EXPECT_EQ(both.min, 10);
  EXPECT_EQ(both.max, 1000);
  const RangeArgument low = parse_range("0.5:");
  EXPECT_EQ(low.min, 0.5);
  EXPECT_FALSE(low.max);
  const RangeArgument high = parse_range(":2e4");
  EXPECT_FALSE(high.min);
  EXPECT_EQ(high.max, 2e4);
}

TEST(FalseColorRange, RejectsMalformedRangesNamingTheOption) {
  for (const char* text : {"", "500", "abc:10", "10:abc", "5:1", "5:5", "1:2:3", "-1:5", ":",
                           "1e999:1e1000", "10 :x"}) {
    try {
      parse_range(text);
      FAIL() << "accepted '" << text << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--range: ", 0), 0u) << e.what();
    }
  }
}

TEST(FalseColorLegend, AddsDocumentedWidthAndMinimumHeight) {
  const Image8 small = append_legend(make_image8(64, 32), {10, 1000, true}, Quantity::kLuminance);
  EXPECT_EQ(small.width, 64 + kLegendWidth);
  EXPECT_EQ(small.height, kLegendMinHeight);
  EXPECT_EQ(small.at(10, 100), kLegendBackground);  // padding below the picture

  const Image8 tall =
      append_legend(make_image8(300, 400, {1, 2, 3}), {0, 500, false}, Quantity::kIlluminance);
  EXPECT_EQ(tall.width, 300 + kLegendWidth);
  EXPECT_EQ(tall.height, 400);
  EXPECT_EQ(tall.at(299, 399), (Rgb8{1, 2, 3}));  // picture unchanged
}

TEST(FalseColorLegend, DrawsBarAndLabels) {
  const int w = 50, h = 300;
  const Image8 out = append_legend(make_image8(w, h), {10, 1000, true}, Quantity::kIlluminance);
  // Bar: MAX colour at the top, MIN colour at the bottom.
  const int bar_x = w + kLegendPad + kLegendBarWidth / 2;
  EXPECT_EQ(out.at(bar_x, kLegendBarTop), kFalseColorRamp.back());
  EXPECT_EQ(out.at(bar_x, h - kLegendBarBottomMargin), kFalseColorRamp.front());
  // Labels: text pixels right of the ticks, spread over the bar's height.
  int label_pixels = 0, top_half = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = w + kLegendLabelX; x < w + kLegendWidth; ++x) {
      if (out.at(x, y) == kLegendForeground) {
        ++label_pixels;
        if (y < h / 2) ++top_half;
      }
    }
  }
  EXPECT_GT(label_pixels, 7 * 20);  // 7 labels of several strokes each
  EXPECT_GT(top_half, 0);
  EXPECT_LT(top_half, label_pixels);
  // Title: the unit above the bar.
  int title_pixels = 0;
  for (int y = 0; y < kLegendBarTop - 10; ++y) {
    for (int x = w; x < w + kLegendWidth; ++x) title_pixels += out.at(x, y) == kLegendForeground;
  }
  EXPECT_GT(title_pixels, 20);
}

TEST(FalseColorLegend, TextIsScaledFontStrokes) {
  Image8 canvas = make_image8(40, 30);
  draw_text(canvas, 2, 3, "1", {255, 255, 255}, 2);
  int lit = 0, top = 30, bottom = 0;
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (canvas.at(x, y) == Rgb8{255, 255, 255}) {
        ++lit;
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  EXPECT_GT(lit, 0);
  EXPECT_EQ(top, 3);
  EXPECT_EQ(bottom - top + 1, kGlyphHeight * 2);
  EXPECT_EQ(text_width("10", 2), 2 * text_width("1", 1) * 2);
}

TEST(FalseColorLegend, LongLabelsAreDrawnInFull) {
  // Regression: the font's vertex buffer was too small for six stroke-heavy digits.
  Image8 canvas = make_image8(120, 20);
  draw_text(canvas, 0, 2, "888888", {255, 255, 255}, 2);
  int rightmost = -1;
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 120; ++x) {
      if (canvas.at(x, y) == Rgb8{255, 255, 255}) rightmost = std::max(rightmost, x);
    }
  }
  EXPECT_GE(rightmost, 5 * text_width("8", 2));  // the sixth glyph is there
  EXPECT_LT(rightmost, text_width("888888", 2));
}

}  // namespace
}  // namespace relight
