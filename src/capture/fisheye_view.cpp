#include "capture/fisheye_view.h"

#include <algorithm>
#include <cmath>

namespace relight {

namespace {

double unnormalised_radius(FisheyeProjection projection, double theta) {
  switch (projection) {
    case FisheyeProjection::kEquisolid:
      return 2 * std::sin(theta / 2);
    case FisheyeProjection::kStereographic:
      return 2 * std::tan(theta / 2);
    case FisheyeProjection::kEquidistant:
      break;
  }
  return theta;
}

}  // namespace

double lens_radius(const FisheyeLens& lens, double theta) {
  return unnormalised_radius(lens.projection, theta) /
         unnormalised_radius(lens.projection, lens.fov_rad / 2);
}

double lens_angle(const FisheyeLens& lens, double radius) {
  const double r = radius * unnormalised_radius(lens.projection, lens.fov_rad / 2);
  switch (lens.projection) {
    case FisheyeProjection::kEquisolid:
      return 2 * std::asin(std::clamp(r / 2, -1.0, 1.0));
    case FisheyeProjection::kStereographic:
      return 2 * std::atan(r / 2);
    case FisheyeProjection::kEquidistant:
      break;
  }
  return r;
}

FisheyeView front_view(const ImageCircle& circle, const FisheyeLens& lens) {
  return {circle, lens, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
}

FisheyeView back_view(const ImageCircle& circle, const FisheyeLens& lens) {
  return {circle, lens, {0, 0, 1}, {-1, 0, 0}, {0, 1, 0}};
}

std::optional<PhotoPoint> photo_point(const FisheyeView& view, Vec3 dir) {
  const double along = dot(dir, view.axis);
  const double x = dot(dir, view.right), y = dot(dir, view.up);
  const double theta = std::atan2(std::hypot(x, y), along);
  if (theta > view.lens.fov_rad / 2) return std::nullopt;
  const double s = std::hypot(x, y);
  const double rho = view.circle.radius * lens_radius(view.lens, theta);
  if (s < 1e-12) return PhotoPoint{view.circle.cx, view.circle.cy};
  return PhotoPoint{view.circle.cx + rho * x / s, view.circle.cy - rho * y / s};
}

std::optional<Vec3> view_direction(const FisheyeView& view, PhotoPoint point) {
  const double dx = point.x - view.circle.cx, dy = view.circle.cy - point.y;
  const double rho = std::hypot(dx, dy) / view.circle.radius;
  if (rho > 1) return std::nullopt;
  const double theta = lens_angle(view.lens, rho);
  if (rho < 1e-12) return view.axis;
  const double s = std::sin(theta) / (rho * view.circle.radius);
  return normalize(std::cos(theta) * view.axis + s * dx * view.right + s * dy * view.up);
}

}  // namespace relight
