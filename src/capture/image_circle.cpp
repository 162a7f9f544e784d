#include "capture/image_circle.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/input_error.h"
#include "math/vec3.h"

namespace relight {

namespace {

struct Point {
  double x = 0, y = 0;
};

ImageCircle fit_circle(const std::vector<Point>& points) {
  // x² + y² + D x + E y + F = 0 in the least-squares sense.
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    a(static_cast<Eigen::Index>(i), 0) = points[i].x;
    a(static_cast<Eigen::Index>(i), 1) = points[i].y;
    a(static_cast<Eigen::Index>(i), 2) = 1;
    b(static_cast<Eigen::Index>(i)) = -(points[i].x * points[i].x + points[i].y * points[i].y);
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const double cx = -def(0) / 2, cy = -def(1) / 2;
  return {cx, cy, std::sqrt(std::max(0.0, cx * cx + cy * cy - def(2)))};
}

}  // namespace

ImageCircle find_image_circle(const Photo& photo, const std::string& where) {
  const int w = photo.width, h = photo.height;
  const int threshold = photo.max_value() / 20;
  const auto lit = [&](int x, int y) {
    const std::size_t o = photo.offset(x, y);
    return std::max({photo.rgb[o], photo.rgb[o + 1], photo.rgb[o + 2]}) > threshold;
  };
  // Rough centre: centroid of the lit pixels (every 4th row and column).
  double sx = 0, sy = 0, n = 0;
  for (int y = 0; y < h; y += 4) {
    for (int x = 0; x < w; x += 4) {
      if (lit(x, y)) {
        sx += x + 0.5;
        sy += y + 0.5;
        n += 1;
      }
    }
  }
  if (n < 16) fail_input(where, "no fisheye image circle found (the photo is dark)");
  const double x0 = sx / n, y0 = sy / n;
  std::vector<Point> edge;
  constexpr int kRays = 720;
  for (int k = 0; k < kRays; ++k) {
    const double a = 2 * kPi * (k + 0.5) / kRays;
    const double dx = std::cos(a), dy = std::sin(a);
    // Distance from the rough centre to the photo's edge along the ray.
    double reach = 1e30;
    if (dx > 1e-9) reach = std::min(reach, (w - 0.5 - x0) / dx);
    if (dx < -1e-9) reach = std::min(reach, (0.5 - x0) / dx);
    if (dy > 1e-9) reach = std::min(reach, (h - 0.5 - y0) / dy);
    if (dy < -1e-9) reach = std::min(reach, (0.5 - y0) / dy);
    int run = 0;
    for (double t = reach; t > 0; t -= 0.5) {
      const int x = static_cast<int>(x0 + t * dx), y = static_cast<int>(y0 + t * dy);
      if (x < 0 || y < 0 || x >= w || y >= h) continue;
      if (!lit(x, y)) {
        run = 0;
        continue;
      }
      if (++run == 3) {
        const double t_edge = t + 1.25;  // the run's first lit sample, + half a step
        if (reach - t_edge > 1.5) edge.push_back({x0 + t_edge * dx, y0 + t_edge * dy});
        break;
      }
    }
  }
  if (edge.size() < 24) fail_input(where, "no fisheye image circle found");
  ImageCircle circle = fit_circle(edge);
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<Point> kept;
    for (const Point& p : edge) {
      if (std::abs(std::hypot(p.x - circle.cx, p.y - circle.cy) - circle.radius) <= 2.0) {
        kept.push_back(p);
      }
    }
    if (kept.size() < 24 || kept.size() == edge.size()) break;
    edge = std::move(kept);
    circle = fit_circle(edge);
  }
  return circle;
}

}  // namespace relight
