// The one placement of a rigid object in a lighting state (docs/lighting-state.md: exterior
// objects, near-field emitters and movable objects): turned by `rotate_deg` about
// the vertical axis through the object's pivot (the centre of its bounding box as the scene
// placed it), counter-clockwise seen from above (the right-handed turn about +y), then moved
// by `translate` (m, from where the scene put it). Pinned by the lighting-state tests of
// exterior objects and emitters (tests/runtime/lighting_state_portals_test.cpp,
// tests/sources/emitters/nearfield_lighting_test.cpp); VerticalTurn by
// tests/math/vertical_turn_test.cpp.
#pragma once

#include <cmath>

#include "math/vec3.h"

namespace relight {

struct Placement {
  Vec3 translate{0, 0, 0};
  double rotate_deg = 0;
  bool operator==(const Placement&) const = default;
};

inline Vec3 placed_point(Vec3 p, Vec3 pivot, const Placement& placement) {
  const double a = radians(placement.rotate_deg), c = std::cos(a), s = std::sin(a);
  const Vec3 d = p - pivot;
  return pivot + Vec3{c * d.x + s * d.z, d.y, -s * d.x + c * d.z} + placement.translate;
}

// A placement that may also hide the object (exterior objects, movable objects).
struct MovablePlacement : Placement {
  bool visible = true;
  bool operator==(const MovablePlacement&) const = default;
};

// A placement's turn about the vertical, its sine and cosine taken once, for loops that turn
// many directions by the same angle.
struct VerticalTurn {
  double c = 1, s = 0;
  explicit VerticalTurn(double rotate_deg)
      : c(std::cos(radians(rotate_deg))), s(std::sin(radians(rotate_deg))) {}
  Vec3 operator()(Vec3 v) const { return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z}; }
  // The turn undone (by −rotate_deg), with the same sine and cosine.
  Vec3 inverse(Vec3 v) const { return {c * v.x - s * v.z, v.y, s * v.x + c * v.z}; }
};

// The same turn applied to a direction (a normal, an aim).
inline Vec3 placed_direction(Vec3 v, const Placement& placement) {
  return VerticalTurn(placement.rotate_deg)(v);
}

}  // namespace relight
