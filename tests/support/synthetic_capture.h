// Synthetic phone captures for `relight capture` (its acceptance test): two 190° fisheye brackets
// rendered from a known equirectangular map, with an off-centre image circle, a known non-linear
// camera response, exposures two stops apart written to EXIF, a dark lens-frame band near the rim
// and a photographer low in the back view. The projection here is written out independently of
// src/capture (equidistant, the documented front/back orientation) so a mistake in the product's
// geometry cannot cancel against the same mistake here.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "image/photo.h"
#include "light/environment.h"
#include "math/equirect.h"

namespace relight::testing {

struct SyntheticCaptureSpec {
  int width = 1200, height = 900;               // photo size (px)
  double centre_dx = 23.5, centre_dy = -17.25;  // circle centre from the photo's centre (px)
  double radius = 430;                          // image circle radius (px)
  double fov_deg = 190;                         // across the diameter
  bool equisolid = false;                       // r = 2f sin(θ/2) instead of r = fθ
  bool linear16 = false;         // 16-bit PNGs, linear (value = 65535 x), no EXIF: pass the times
  int shots = 5;                 // exposures, two stops apart
  double band_inner_deg = 92.5;  // the lens frame's dark band: from here to the rim
  double band_factor = 0.08;     // its darkening
  bool photographer = true;      // a dark figure low in the back view
  int jpeg_quality = 95;
  int supersample = 3;              // k × k samples a pixel (anti-aliases the circle's edge)
  double middle_time_s = 1.0 / 60;  // the middle shot's exposure time
  // A camera that records ISO and f-number follows the reflected-light meter equation
  // (ISO 2720, K = 12.5): x(128) = true_response⁻¹(128) at L = K N²/(t S). Unset: the gain
  // puts the map's log-average at x = 0.18 in the middle shot.
  std::optional<double> iso, f_number;
  double back_iso_factor = 1;  // the back bracket shot at this times the ISO (with iso set)
};

// A smaller capture for tests that need a map, not the acceptance: 800 × 600 photos.
inline SyntheticCaptureSpec small_capture_spec() {
  SyntheticCaptureSpec spec;
  spec.width = 800;
  spec.height = 600;
  spec.radius = 285;
  return spec;
}

// The camera's response: pixel value / 255 = f(x) for exposure x (x = 1 saturates),
// f(x) = 1.1 u / (1 + 0.1 u), u = x^0.45 — concave like a phone's tone curve.
inline double true_response(double x) {
  const double u = std::pow(std::max(x, 0.0), 0.45);
  return std::min(1.0, 1.1 * u / (1 + 0.1 * u));
}
// Its inverse: the exposure that gives pixel value z.
inline double true_inverse_response(double z) {
  const double y = z / 255.0;
  return std::pow(y / (1.1 - 0.1 * y), 1 / 0.45);
}

// The photographer's directions: someone crouching just south of the camera — within 18° of
// south's azimuth (the back view's axis), elevation −84° to −30° — so only the back view sees
// them.
inline bool photographer_direction(Vec3 d) {
  const double elevation = std::asin(std::clamp(d.y, -1.0, 1.0)) * 180 / kPi;
  const double azimuth_from_south = std::atan2(-d.x, d.z) * 180 / kPi;
  return elevation < -30 && elevation > -84 && std::abs(azimuth_from_south) < 18;
}

struct SyntheticCapture {
  std::vector<std::filesystem::path> front, back;
  std::vector<double> times;  // seconds, per shot (both brackets)
  double circle_cx = 0, circle_cy = 0;
};

namespace detail {

// Radiance seen by a view at photo point (x, y), or black outside the circle.
inline Rgb synthetic_pixel(const EquirectMap& map, const SyntheticCaptureSpec& s, bool front,
                           double x, double y, double cx, double cy) {
  const double dx = x - cx, dy = cy - y;
  const double r = std::hypot(dx, dy) / s.radius;
  if (r > 1) return {};
  const double half_fov = s.fov_deg / 2 * kPi / 180;
  const double theta =
      s.equisolid ? 2 * std::asin(std::min(1.0, r * std::sin(half_fov / 2))) : r * half_fov;
  // Front: axis −z, right +x, up +y. Back: axis +z, right −x, up +y.
  const Vec3 axis = front ? Vec3{0, 0, -1} : Vec3{0, 0, 1};
  const Vec3 right = front ? Vec3{1, 0, 0} : Vec3{-1, 0, 0};
  const Vec3 up{0, 1, 0};
  const double k = r > 1e-12 ? std::sin(theta) / (r * s.radius) : 0;
  const Vec3 d = normalize(std::cos(theta) * axis + k * dx * right + k * dy * up);
  const EquirectTexel t = equirect_texel(map.width, map.height, d);
  Rgb value = map.texels[static_cast<std::size_t>(t.j) * map.width + t.i];
  if (theta * 180 / kPi > s.band_inner_deg) value *= s.band_factor;
  if (!front && s.photographer && photographer_direction(d)) {
    value = Rgb{0.6, 0.7, 1.0} * (0.1 * luminance(value));
  }
  return value;
}

}  // namespace detail

// The exposure gain (x per cd/m²·s) of a capture: the middle shot puts the map's log-average
// luminance at x = 0.18, as a phone's automatic exposure would.
inline double true_inverse_response(double z);
inline double capture_gain(const EquirectMap& map, const SyntheticCaptureSpec& s) {
  if (s.iso && s.f_number) {
    return true_inverse_response(128) * *s.iso / (12.5 * *s.f_number * *s.f_number);
  }
  double log_sum = 0;
  for (const Rgb& v : map.texels) log_sum += std::log(std::max(luminance(v), 1e-9));
  const double log_average = std::exp(log_sum / static_cast<double>(map.texels.size()));
  return 0.18 / (log_average * s.middle_time_s);
}

// The map with every channel limited to what the shortest shot records at x = 0.8: a room
// whose brightest surface is within the bracket, so nothing clips.
inline EquirectMap within_bracket(EquirectMap map, const SyntheticCaptureSpec& s = {}) {
  const double shortest = s.middle_time_s * std::pow(4.0, -(s.shots - 1) / 2.0);
  const double limit = 0.8 / (capture_gain(map, s) * shortest);
  for (Rgb& v : map.texels) {
    v = {std::min(v.r, limit), std::min(v.g, limit), std::min(v.b, limit)};
  }
  return map;
}

// Writes front_1.jpg … back_5.jpg into `folder`, exposures 4× apart around middle_time_s.
inline SyntheticCapture make_synthetic_capture(const EquirectMap& map,
                                               const std::filesystem::path& folder,
                                               const SyntheticCaptureSpec& s = {}) {
  SyntheticCapture capture;
  capture.circle_cx = s.width / 2.0 + s.centre_dx;
  capture.circle_cy = s.height / 2.0 + s.centre_dy;
  const double gain = capture_gain(map, s);
  for (int k = 0; k < s.shots; ++k) {
    capture.times.push_back(s.middle_time_s * std::pow(4.0, k - (s.shots - 1) / 2.0));
  }
  for (const bool front : {true, false}) {
    const double view_gain = front ? gain : gain * s.back_iso_factor;
    const std::optional<double> view_iso =
        s.iso ? std::optional<double>(*s.iso * (front ? 1 : s.back_iso_factor)) : std::nullopt;
    // Radiance per pixel, k × k samples so the circle's edge is anti-aliased.
    std::vector<Rgb> radiance(static_cast<std::size_t>(s.width) * s.height);
    const int k = s.supersample;
    for (int y = 0; y < s.height; ++y) {
      for (int x = 0; x < s.width; ++x) {
        Rgb sum;
        for (int sy = 0; sy < k; ++sy) {
          for (int sx = 0; sx < k; ++sx) {
            sum += detail::synthetic_pixel(map, s, front, x + (sx + 0.5) / k, y + (sy + 0.5) / k,
                                           capture.circle_cx, capture.circle_cy);
          }
        }
        radiance[static_cast<std::size_t>(y) * s.width + x] = sum / static_cast<double>(k * k);
      }
    }
    for (int k = 0; k < s.shots; ++k) {
      const double t = capture.times[static_cast<std::size_t>(k)];
      const std::string name = (front ? "front_" : "back_") + std::to_string(k + 1);
      const std::filesystem::path file = folder / (name + (s.linear16 ? ".png" : ".jpg"));
      if (s.linear16) {
        cv::Mat bgr(s.height, s.width, CV_16UC3);
        for (std::size_t p = 0; p < radiance.size(); ++p) {
          const Rgb v = radiance[p] * (view_gain * t);
          const auto q = [](double x) {
            return static_cast<std::uint16_t>(std::lround(65535 * std::clamp(x, 0.0, 1.0)));
          };
          bgr.at<cv::Vec3w>(static_cast<int>(p / s.width), static_cast<int>(p % s.width)) = {
              q(v.b), q(v.g), q(v.r)};
        }
        cv::imwrite(file.string(), bgr);
      } else {
        Photo photo{s.width, s.height, 8, std::vector<std::uint16_t>(radiance.size() * 3)};
        for (std::size_t p = 0; p < radiance.size(); ++p) {
          const Rgb v = radiance[p] * (view_gain * t);
          const double c[3] = {v.r, v.g, v.b};
          for (int ch = 0; ch < 3; ++ch) {
            photo.rgb[3 * p + ch] =
                static_cast<std::uint16_t>(std::lround(255 * true_response(c[ch])));
          }
        }
        write_photo_jpeg(file, photo, s.jpeg_quality, {t, s.f_number, view_iso});
      }
      (front ? capture.front : capture.back).push_back(file);
    }
  }
  return capture;
}

}  // namespace relight::testing
