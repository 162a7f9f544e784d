// Images as the renderer produces them (Image: linear Rec.709 RGB in physical units) and as they
// are displayed (Image8: 8-bit sRGB-encoded RGB). Keeping the two apart makes every conversion from
// physical values to display values an explicit step (tone_map.h, false_color.h) and keeps the HDR
// values unchanged for EXR.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/rgb.h"

namespace relight {

// Row-major, top row first. Each channel holds luminance in cd/m² or illuminance in lux;
// luminance(pixel) is the photometric quantity. A pixel that sees no surface may be NaN:
// false colour draws it neutral, tone mapping draws it black.
struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;

  Rgb& at(int x, int y) { return pixels[index(x, y)]; }
  const Rgb& at(int x, int y) const { return pixels[index(x, y)]; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
};

Image make_image(int width, int height, Rgb fill = {});

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(Rgb8, Rgb8) = default;
};

// Row-major, top row first, 3 bytes (R, G, B) per pixel, sRGB-encoded.
struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  Rgb8 at(int x, int y) const {
    const std::size_t i = offset(x, y);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  void set(int x, int y, Rgb8 c) {
    const std::size_t i = offset(x, y);
    rgb[i] = c.r;
    rgb[i + 1] = c.g;
    rgb[i + 2] = c.b;
  }
  std::size_t offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x));
  }
};

Image8 make_image8(int width, int height, Rgb8 fill = {});

// True when the pixel buffer matches width × height (both positive).
bool is_valid(const Image& image);
bool is_valid(const Image8& image);

}  // namespace relight
