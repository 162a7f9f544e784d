// Camera-style tone mapping; the formulas and their sources are in tone_map.h.
#include "render/tone_map.h"

#include <cmath>

#include "math/srgb.h"

namespace relight {

namespace {

constexpr double kSaturationFactor = 1.2;  // 78 / (q · S) with q = 0.65, S = 100

double display_value(double luminance, double scale) {
  if (!(luminance > 0)) return 0.0;  // negative, zero and NaN
  return srgb_encode(highlight_rolloff(luminance * scale));
}

}  // namespace

double saturation_luminance(double ev100) {
  return kSaturationFactor * std::exp2(ev100);
}

double exposure_scale(double ev100) {
  return 1.0 / saturation_luminance(ev100);
}

std::optional<double> log_average_luminance(const Image& hdr) {
  double sum = 0;
  std::size_t count = 0;
  for (const Rgb& p : hdr.pixels) {
    const double y = luminance(p);
    if (std::isfinite(y) && y > 0) {
      sum += std::log(y);
      ++count;
    }
  }
  if (count == 0) return std::nullopt;
  return std::exp(sum / static_cast<double>(count));
}

double auto_exposure_ev100(const Image& hdr) {
  const std::optional<double> average = log_average_luminance(hdr);
  if (!average) return 0.0;
  return std::log2(*average / (kSaturationFactor * kAutoExposureKey));
}

double highlight_rolloff(double x) {
  if (x <= kShoulderStart) return x;
  const double u = (x - kShoulderStart) / (1.0 - kShoulderStart);
  if (std::isinf(u)) return 1.0;
  return kShoulderStart + (1.0 - kShoulderStart) * u / (1.0 + u);
}

std::uint8_t quantize_8bit(double display) {
  if (!(display > 0)) return 0;
  if (display >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(255.0 * display));
}

ToneMapped tone_map(const Image& hdr, std::optional<double> ev100) {
  const double ev = ev100 ? *ev100 : auto_exposure_ev100(hdr);
  const double scale = exposure_scale(ev);
  ToneMapped result{make_image8(hdr.width, hdr.height), ev};
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      const Rgb& p = hdr.at(x, y);
      result.image.set(
          x, y,
          {quantize_8bit(display_value(p.r, scale)), quantize_8bit(display_value(p.g, scale)),
           quantize_8bit(display_value(p.b, scale))});
    }
  }
  return result;
}

}  // namespace relight
