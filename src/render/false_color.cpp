// False-colour mapping of Y through the ramp (see false_color.h).
#include "render/false_color.h"

#include <algorithm>
#include <cmath>

#include "render/false_color_legend.h"

namespace relight {

namespace {

std::uint8_t lerp(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(a + (b - a) * f));
}

}  // namespace

Rgb8 ramp_color(double t) {
  if (std::isnan(t)) return kNoSurfaceColor;
  const double position = std::clamp(t, 0.0, 1.0) * (kFalseColorRamp.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), kFalseColorRamp.size() - 2);
  const double f = position - static_cast<double>(i);
  const Rgb8 a = kFalseColorRamp[i], b = kFalseColorRamp[i + 1];
  return {lerp(a.r, b.r, f), lerp(a.g, b.g, f), lerp(a.b, b.b, f)};
}

Image8 false_color_pixels(const Image& hdr, const FalseColorScale& scale) {
  Image8 out = make_image8(hdr.width, hdr.height);
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      out.set(x, y, ramp_color(scale_position(scale, luminance(hdr.at(x, y)))));
    }
  }
  return out;
}

FalseColorImage render_false_color(const Image& hdr, const FalseColor& request) {
  const FalseColorScale scale = resolve_scale(hdr, request);
  return {append_legend(false_color_pixels(hdr, scale), scale, request.quantity), scale};
}

}  // namespace relight
