#include "scene/camera.h"

#include <cmath>

namespace relight {

PinholeCamera make_pinhole_camera(const Camera& c, int width, int height) {
  PinholeCamera p;
  p.eye = c.eye;
  p.forward = normalize(c.target - c.eye);
  p.right = normalize(cross(p.forward, c.up));
  p.up = cross(p.right, p.forward);
  p.tan_half_fov = std::tan(radians(c.fov_deg) / 2);
  p.width = width;
  p.height = height;
  return p;
}

Vec3 PinholeCamera::direction(double px, double py) const {
  const double aspect = static_cast<double>(width) / height;
  const double sx = (2 * px / width - 1) * tan_half_fov * aspect;
  const double sy = (1 - 2 * py / height) * tan_half_fov;
  return normalize(forward + right * sx + up * sy);
}

Camera default_camera(const Bounds& b) {
  const Vec3 centre = (b.min + b.max) * 0.5;
  const Vec3 size = b.max - b.min;
  Camera c;
  c.name = "default";
  c.eye = {centre.x, b.min.y + 0.55 * size.y, b.max.z - 0.05 * size.z};
  c.target = {centre.x, b.min.y + 0.35 * size.y, b.min.z};
  c.fov_deg = 70;
  return c;
}

}  // namespace relight
