#include "capture/view_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "math/equirect.h"

namespace relight {

namespace {

struct Reduced {
  cv::Mat radiance;  // CV_32FC3
  cv::Mat clipped;   // CV_32F, share of clipped pixels
  double scale = 1;  // reduced pixels per photo pixel
};

Reduced reduce(const HdrPhoto& photo, const FisheyeView& view, int width) {
  cv::Mat radiance(photo.height, photo.width, CV_32FC3);
  cv::Mat clipped(photo.height, photo.width, CV_32F);
  for (int y = 0; y < photo.height; ++y) {
    auto* row = radiance.ptr<cv::Vec3f>(y);
    auto* crow = clipped.ptr<float>(y);
    for (int x = 0; x < photo.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * photo.width + x;
      const Rgb& v = photo.radiance[p];
      row[x] = {static_cast<float>(v.r), static_cast<float>(v.g), static_cast<float>(v.b)};
      crow[x] = photo.clipped[p];
    }
  }
  // Photo pixels per radian at the centre against two samples per texel.
  const double dr_dtheta = (lens_radius(view.lens, 1e-3) / 1e-3) * view.circle.radius;
  const double wanted = 2 * width / (2 * kPi);
  const double scale = std::min(1.0, wanted / dr_dtheta);
  if (scale > 0.9) return {radiance, clipped, 1};
  Reduced r;
  r.scale = scale;
  const cv::Size size(std::max(1, static_cast<int>(std::lround(photo.width * scale))),
                      std::max(1, static_cast<int>(std::lround(photo.height * scale))));
  cv::resize(radiance, r.radiance, size, 0, 0, cv::INTER_AREA);
  cv::resize(clipped, r.clipped, size, 0, 0, cv::INTER_AREA);
  r.scale = static_cast<double>(size.width) / photo.width;
  return r;
}

template <typename T>
T bilinear(const cv::Mat& m, double x, double y) {
  // x, y in pixel coordinates (centres at +0.5); clamped at the border.
  const double fx = std::clamp(x - 0.5, 0.0, m.cols - 1.0);
  const double fy = std::clamp(y - 0.5, 0.0, m.rows - 1.0);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const int x1 = std::min(x0 + 1, m.cols - 1), y1 = std::min(y0 + 1, m.rows - 1);
  const auto ax = static_cast<float>(fx - x0), ay = static_cast<float>(fy - y0);
  return (m.at<T>(y0, x0) * (1 - ax) + m.at<T>(y0, x1) * ax) * (1 - ay) +
         (m.at<T>(y1, x0) * (1 - ax) + m.at<T>(y1, x1) * ax) * ay;
}

}  // namespace

ViewMap project_view(const HdrPhoto& photo, const FisheyeView& view, int width) {
  const int height = width / 2;
  const Reduced reduced = reduce(photo, view, width);
  const std::size_t texels = static_cast<std::size_t>(width) * height;
  ViewMap map{width,
              height,
              std::vector<Rgb>(texels),
              std::vector<float>(texels),
              std::vector<std::uint8_t>(texels, 0),
              std::vector<std::uint8_t>(texels, 0)};
  tbb::parallel_for(0, height, [&](int j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * width + i;
      map.theta[t] = static_cast<float>(std::acos(
          std::clamp(dot(equirect_texel_direction(width, height, i, j), view.axis), -1.0, 1.0)));
      cv::Vec3f sum(0, 0, 0);
      float clipped = 0;
      bool seen = true;
      for (int sy = 0; sy < 3 && seen; ++sy) {
        for (int sx = 0; sx < 3; ++sx) {
          const Vec3 dir =
              equirect_direction((i + (sx + 0.5) / 3) / width, (j + (sy + 0.5) / 3) / height);
          const std::optional<PhotoPoint> p = photo_point(view, dir);
          if (!p ||
              std::hypot(p->x - view.circle.cx, p->y - view.circle.cy) > view.circle.radius - 0.5) {
            seen = false;
            break;
          }
          sum += bilinear<cv::Vec3f>(reduced.radiance, p->x * reduced.scale, p->y * reduced.scale);
          clipped += bilinear<float>(reduced.clipped, p->x * reduced.scale, p->y * reduced.scale);
        }
      }
      if (!seen) continue;
      map.seen[t] = 1;
      map.radiance[t] = Rgb{sum[0], sum[1], sum[2]} / 9.0;
      map.clipped[t] = clipped > 0 ? 1 : 0;
    }
  });
  return map;
}

}  // namespace relight
