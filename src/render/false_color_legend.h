// The legend beside a false-colour picture: a vertical colour bar (MIN at the bottom,
// MAX at the top) with tick labels in physical units, the unit as title ("lx" or
// "cd/m2") and below it "log scale" or "linear". Text is stb_easy_font (Debian's
// libstb-dev), whose glyphs are axis-aligned 1-unit strokes; they are rasterised here at
// kTextScale pixels per unit for legibility.
//
// Layout, in pixels from the legend's top-left corner (the legend is kLegendWidth wide):
//  * title at (kLegendPad, kLegendTitleY), scale kind at (kLegendPad, kLegendScaleKindY);
//  * colour bar kLegendBarWidth wide from x = kLegendPad, from y = kLegendBarTop down to
//    height − kLegendBarBottomMargin;
//  * tick marks kLegendTickLength long right of the bar, labels from x = kLegendLabelX,
//    centred on their tick.
// The output is max(picture height, kLegendMinHeight) tall; a shorter picture is padded
// below with the legend background.
#pragma once

#include <string_view>

#include "image/image.h"
#include "render/false_color_scale.h"

namespace relight {

inline constexpr int kLegendWidth = 160;
inline constexpr int kLegendMinHeight = 256;
inline constexpr int kTextScale = 2;
inline constexpr int kLegendPad = 14;
inline constexpr int kLegendTitleY = 10;
inline constexpr int kLegendScaleKindY = 30;
inline constexpr int kLegendBarWidth = 26;
inline constexpr int kLegendBarTop = 60;
inline constexpr int kLegendBarBottomMargin = 20;
inline constexpr int kLegendTickLength = 6;
inline constexpr int kLegendLabelX = kLegendPad + kLegendBarWidth + kLegendTickLength + 6;
inline constexpr Rgb8 kLegendBackground = {32, 32, 32};
inline constexpr Rgb8 kLegendForeground = {235, 235, 235};

// Picture with the legend for scale appended on its right.
Image8 append_legend(const Image8& picture, const FalseColorScale& scale, Quantity quantity);

// Draws ASCII text with its top-left corner at (x, y), each font unit scale × scale
// pixels; parts outside the image are clipped.
void draw_text(Image8& image, int x, int y, std::string_view text, Rgb8 colour, int scale);
// Width in pixels of text drawn by draw_text.
int text_width(std::string_view text, int scale);
inline constexpr int kGlyphHeight = 7;  // font units from the top of a digit to its base

}  // namespace relight
