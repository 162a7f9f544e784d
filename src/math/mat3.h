// 3×3 matrices, row-major, for rotations of directions and of SH coefficient vectors
// (math/sh_rotation.h). A rotation R maps a direction d to R·d.
#pragma once

#include <array>
#include <cmath>

#include "math/frame.h"
#include "math/vec3.h"

namespace relight {

struct Mat3 {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // m[row][col]

  constexpr double operator()(int row, int col) const { return m[row][col]; }
  constexpr double& operator()(int row, int col) { return m[row][col]; }
};

constexpr Mat3 mat3_identity() {
  return {};
}
// The matrix whose columns are a, b, c.
constexpr Mat3 mat3_from_columns(Vec3 a, Vec3 b, Vec3 c) {
  return {{{{a.x, b.x, c.x}, {a.y, b.y, c.y}, {a.z, b.z, c.z}}}};
}
// Local → world of a Frame: columns t, b, n, so mat·local == frame.to_world(local).
constexpr Mat3 mat3_from_frame(const Frame& f) {
  return mat3_from_columns(f.t, f.b, f.n);
}

constexpr Vec3 operator*(const Mat3& a, Vec3 v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
constexpr Mat3 operator*(const Mat3& a, const Mat3& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return r;
}
constexpr Mat3 transpose(const Mat3& a) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

// Right-handed rotation by `angle` radians about the unit `axis` (Rodrigues' formula).
inline Mat3 mat3_rotation(Vec3 axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  return {{{{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
            {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
            {t * x * z - s * y, t * y * z + s * x, t * z * z + c}}}};
}

}  // namespace relight
