#include "math/frame.h"

#include <cmath>

namespace relight {

Frame frame_from_normal(Vec3 n) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  const Vec3 t{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  const Vec3 bt{b, sign + n.y * n.y * a, -n.y};
  return {t, bt, n};
}

Frame frame_from_normal_and_hint(Vec3 n, Vec3 hint) {
  const Vec3 t = hint - n * dot(hint, n);
  const double len = length(t);
  if (len < 1e-9) return frame_from_normal(n);
  const Vec3 tn = t / len;
  return {tn, cross(n, tn), n};
}

}  // namespace relight
