#include "capture/outliers.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "math/equirect.h"

namespace relight {

namespace {

constexpr double kDarker = 1.0986;           // ln 3
constexpr double kMinSolidAngle = 0.02;      // sr
constexpr double kMaxMeanElevation = -35;    // degrees
constexpr double kMaxLowestElevation = -65;  // degrees

}  // namespace

std::vector<std::uint8_t> find_outliers(const BlendedMap& map) {
  const int w = map.width, h = map.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  std::vector<std::uint8_t> outlier(count, 0);
  std::vector<float> log_y(count, 0);
  std::vector<float> known;
  for (std::size_t t = 0; t < count; ++t) {
    if (map.hole[t]) continue;
    log_y[t] = static_cast<float>(std::log(std::max(luminance(map.radiance[t]), 1e-12)));
    known.push_back(log_y[t]);
  }
  if (known.size() < 16) return outlier;
  const auto at = [&](double q) {
    auto it = known.begin() + static_cast<std::ptrdiff_t>(q * (known.size() - 1));
    std::nth_element(known.begin(), it, known.end());
    return *it;
  };
  const float lo = at(0.005), hi = std::max(at(0.995), lo + 1e-3f);
  const float step = (hi - lo) / 255;
  cv::Mat quantised(h, w, CV_8U);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * w + i;
      // A hole reads as the middle of the range so that it pulls the median neither way.
      const float v = map.hole[t] ? 127.5f : (std::clamp(log_y[t], lo, hi) - lo) / step;
      quantised.at<std::uint8_t>(j, i) = static_cast<std::uint8_t>(std::lround(v));
    }
  }
  cv::Mat background;
  const int window = std::max(3, (w / 4) | 1);
  cv::medianBlur(quantised, background, window);
  cv::Mat candidate(h, w, CV_8U, cv::Scalar(0));
  for (int j = h / 2; j < h; ++j) {  // below the horizon
    for (int i = 0; i < w; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * w + i;
      if (map.hole[t]) continue;
      const float expected = lo + step * background.at<std::uint8_t>(j, i);
      if (std::clamp(log_y[t], lo, hi) < expected - kDarker) candidate.at<std::uint8_t>(j, i) = 1;
    }
  }
  // An opening (2° radius) cuts thin bridges between a person and the dark furniture behind
  // them, and drops thin dark things (chair legs, cables).
  const int radius = std::max(1, static_cast<int>(std::lround(2 * w / 360.0)));
  cv::morphologyEx(candidate, candidate, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1}));
  cv::Mat labels;
  const int regions = cv::connectedComponents(candidate, labels, 8, CV_32S);
  // Per region: solid angle, its solid-angle-weighted mean elevation, its lowest elevation.
  struct Region {
    double solid_angle = 0, elevation_sum = 0, lowest = 90;
  };
  std::vector<Region> region(static_cast<std::size_t>(regions));
  for (int j = 0; j < h; ++j) {
    const double omega = equirect_row_solid_angle(w, h, j);
    const double elevation = 90 - 180 * (j + 0.5) / h;
    for (int i = 0; i < w; ++i) {
      Region& r = region[static_cast<std::size_t>(labels.at<int>(j, i))];
      r.solid_angle += omega;
      r.elevation_sum += omega * elevation;
      r.lowest = std::min(r.lowest, elevation);
    }
  }
  const auto is_outlier = [&](int label) {
    if (label <= 0) return false;
    const Region& r = region[static_cast<std::size_t>(label)];
    return r.solid_angle >= kMinSolidAngle &&
           r.elevation_sum / r.solid_angle <= kMaxMeanElevation && r.lowest <= kMaxLowestElevation;
  };
  cv::Mat kept(h, w, CV_8U, cv::Scalar(0));
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      if (is_outlier(labels.at<int>(j, i))) kept.at<std::uint8_t>(j, i) = 1;
    }
  }
  cv::dilate(kept, kept,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1}));
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * w + i;
      outlier[t] = (kept.at<std::uint8_t>(j, i) && !map.hole[t]) ? 1 : 0;
    }
  }
  return outlier;
}

}  // namespace relight
