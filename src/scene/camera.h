// Pinhole camera of the scene format: eye, target, up, vertical field of view.
// Pixel (x, y) with y = 0 at the top row; sub-pixel offsets in [0,1).
#pragma once

#include "math/vec3.h"
#include "scene/scene.h"

namespace relight {

struct PinholeCamera {
  Vec3 eye, forward, right, up;  // unit vectors; right × up = -forward (y up image)
  double tan_half_fov = 0;
  int width = 0, height = 0;

  // Unit direction through the image point (px + dx, py + dy).
  Vec3 direction(double px, double py) const;
};

PinholeCamera make_pinhole_camera(const Camera& camera, int width, int height);
// A camera for scenes without one: inside the bounds, looking along -z from near +z.
Camera default_camera(const Bounds& bounds);

}  // namespace relight
