// Moving an object in a lighting state (docs/lighting-state.md: exterior objects, near-field
// emitters): turned by rotate_deg about the vertical axis through its pivot, counter-clockwise
// seen from above (the right-handed turn about +y), then moved by translate.
#pragma once

#include <cmath>

#include "math/vec3.h"

namespace relight {

inline Vec3 placed_point(Vec3 p, Vec3 pivot, double rotate_deg, Vec3 translate) {
  const double a = radians(rotate_deg), c = std::cos(a), s = std::sin(a);
  const Vec3 d = p - pivot;
  return pivot + Vec3{c * d.x + s * d.z, d.y, -s * d.x + c * d.z} + translate;
}

}  // namespace relight
