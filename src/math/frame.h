// Orthonormal frames: local (t, b, n) <-> world. Used for cosine sampling about a
// surface normal and for luminaire frames (aim = photometric γ = 0 axis).
#pragma once

#include "math/vec3.h"

namespace relight {

struct Frame {
  Vec3 t, b, n;  // right-handed: cross(t, b) == n

  Vec3 to_world(Vec3 local) const { return t * local.x + b * local.y + n * local.z; }
  Vec3 to_local(Vec3 world) const { return {dot(world, t), dot(world, b), dot(world, n)}; }
};

// Any frame with the given unit normal (Duff et al. 2017, "Building an orthonormal
// basis, revisited"): continuous except at n.z = -1 handled by the sign.
Frame frame_from_normal(Vec3 n);

// Frame with n = unit normal and t = the part of `hint` orthogonal to n (normalised);
// falls back to frame_from_normal when hint is parallel to n.
Frame frame_from_normal_and_hint(Vec3 n, Vec3 hint);

}  // namespace relight
