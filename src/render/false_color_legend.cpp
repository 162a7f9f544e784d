// False-colour legend: colour bar, ticks and labels (layout in false_color_legend.h).
#include "render/false_color_legend.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/false_color.h"

// stb_easy_font is a C header of static functions, not all of which are used here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace relight {

namespace {

constexpr Rgb8 kBarFrame = {150, 150, 150};

void fill_rect(Image8& image, int x0, int y0, int x1, int y1, Rgb8 colour) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width);
  y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) image.set(x, y, colour);
  }
}

// Printable ASCII only: the font covers 32..126.
std::string printable(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c < 32 || c > 126) c = '?';
  }
  return out;
}

}  // namespace

int text_width(std::string_view text, int scale) {
  std::string copy = printable(text);
  return scale * stb_easy_font_width(copy.data());
}

void draw_text(Image8& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  std::string copy = printable(text);
  // Each quad is 4 vertices of {float x, y, z; uint8 rgba[4]} (16 bytes). The header
  // says ~270 bytes a character on average; digits such as '0' and '8' need more, and a
  // short buffer silently truncates, so allow 16 quads a character.
  constexpr int kVertexBytes = 16;
  std::vector<char> buffer(std::size_t{16} * 4 * kVertexBytes * (copy.size() + 1));
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(),
                                        static_cast<int>(buffer.size()));
  for (int q = 0; q < quads; ++q) {
    float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
    for (int v = 0; v < 4; ++v) {
      float xy[2];
      std::copy_n(buffer.data() + static_cast<std::ptrdiff_t>(4 * q + v) * kVertexBytes, sizeof xy,
                  reinterpret_cast<char*>(xy));
      x0 = std::min(x0, xy[0]);
      x1 = std::max(x1, xy[0]);
      y0 = std::min(y0, xy[1]);
      y1 = std::max(y1, xy[1]);
    }
    fill_rect(image, x + static_cast<int>(std::lround(x0 * scale)),
              y + static_cast<int>(std::lround(y0 * scale)),
              x + static_cast<int>(std::lround(x1 * scale)),
              y + static_cast<int>(std::lround(y1 * scale)), colour);
  }
}

Image8 append_legend(const Image8& picture, const FalseColorScale& scale, Quantity quantity) {
  const int height = std::max(picture.height, kLegendMinHeight);
  Image8 out = make_image8(picture.width + kLegendWidth, height, kLegendBackground);
  for (int y = 0; y < picture.height; ++y) {
    std::copy_n(picture.rgb.begin() + static_cast<std::ptrdiff_t>(picture.offset(0, y)),
                3 * picture.width, out.rgb.begin() + static_cast<std::ptrdiff_t>(out.offset(0, y)));
  }

  const int left = picture.width;
  draw_text(out, left + kLegendPad, kLegendTitleY, unit_label(quantity), kLegendForeground,
            kTextScale);
  draw_text(out, left + kLegendPad, kLegendScaleKindY, scale.logarithmic ? "log scale" : "linear",
            kLegendForeground, kTextScale);

  // Colour bar, MAX at the top, with a one-pixel frame.
  const int bar_x0 = left + kLegendPad, bar_x1 = bar_x0 + kLegendBarWidth;
  const int top = kLegendBarTop, bottom = height - kLegendBarBottomMargin;
  fill_rect(out, bar_x0 - 1, top - 1, bar_x1 + 1, bottom + 2, kBarFrame);
  for (int y = top; y <= bottom; ++y) {
    const double t = static_cast<double>(bottom - y) / (bottom - top);
    fill_rect(out, bar_x0, y, bar_x1, y + 1, ramp_color(t));
  }

  const int label_height = kGlyphHeight * kTextScale;
  for (const double value : scale_ticks(scale)) {
    const int y =
        bottom - static_cast<int>(std::lround(scale_position(scale, value) * (bottom - top)));
    fill_rect(out, bar_x1 + 1, y, bar_x1 + 1 + kLegendTickLength, y + kTextScale,
              kLegendForeground);
    draw_text(out, left + kLegendLabelX, y + kTextScale / 2 - label_height / 2, format_tick(value),
              kLegendForeground, kTextScale);
  }
  return out;
}

}  // namespace relight
