// Cubemap layout, texel solid angles and SH projection; see cubemap.h.
#include "math/cubemap.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "math/sh.h"
#include "math/tabulated.h"

namespace relight {
namespace {

double area_element_integral(double u, double v) {
  return std::atan2(u * v, std::sqrt(1.0 + u * u + v * v));
}

}  // namespace

Vec3 cubemap_face_point(int face, double u, double v) {
  switch (face) {
    case kPosX:
      return {1.0, -v, -u};
    case kNegX:
      return {-1.0, -v, u};
    case kPosY:
      return {u, 1.0, v};
    case kNegY:
      return {u, -1.0, -v};
    case kPosZ:
      return {u, -v, 1.0};
    default:
      return {-u, -v, -1.0};
  }
}

namespace {

// Y_lm(centre) · Ω per texel and coefficient (texel-major, sh_count(order) a texel).
std::vector<double> tabulate_sh_weights(int order, int n) {
  const std::vector<Vec3>& directions = cubemap_texel_directions(n);
  const std::vector<double>& omega = cubemap_solid_angles(n);
  const auto k = static_cast<std::size_t>(sh_count(order));
  std::vector<double> table(directions.size() * k);
  std::vector<double> y(k);
  for (std::size_t t = 0; t < directions.size(); ++t) {
    const CubemapTexel texel = cubemap_texel_from_index(n, t);
    sh_eval(order, directions[t], y);
    for (std::size_t b = 0; b < k; ++b) table[t * k + b] = y[b] * omega[texel.j * n + texel.i];
  }
  return table;
}

// The SH weights of every texel, tabulated once per (order, N) like the solid angles: a shell
// projects its cubemap whenever its sky changes (every hour of `relight annual`).
const std::vector<double>& cubemap_sh_weights(int order, int n) {
  return tabulated<std::vector<double>>(std::pair{order, n}, [](std::pair<int, int> key) {
    return tabulate_sh_weights(key.first, key.second);
  });
}

template <class T>
std::vector<T> project(int order, int n, std::span<const T> texels) {
  assert(texels.size() == cubemap_texel_count(n));
  const std::vector<double>& table = cubemap_sh_weights(order, n);
  const auto k = static_cast<std::size_t>(sh_count(order));
  std::vector<T> c(k);
  for (std::size_t t = 0; t < texels.size(); ++t) {
    const T& value = texels[t];
    if (value == T{}) continue;  // e.g. the half of a shell behind its portal
    const double* y = table.data() + t * k;
    for (std::size_t b = 0; b < k; ++b) c[b] += value * y[b];
  }
  return c;
}

std::vector<Vec3> tabulate_texel_directions(int n) {
  std::vector<Vec3> d(cubemap_texel_count(n));
  for (std::size_t t = 0; t < d.size(); ++t) {
    d[t] = cubemap_texel_direction(n, cubemap_texel_from_index(n, t));
  }
  return d;
}

}  // namespace

const std::vector<Vec3>& cubemap_texel_directions(int n) {
  return tabulated<std::vector<Vec3>>(n, [](int k) { return tabulate_texel_directions(k); });
}

Vec3 cubemap_direction(CubemapCoord c) {
  return normalize(cubemap_face_point(c.face, 2.0 * c.s - 1.0, 2.0 * c.t - 1.0));
}

Vec3 cubemap_texel_direction(int n, CubemapTexel c) {
  return cubemap_direction({c.face, (c.i + 0.5) / n, (c.j + 0.5) / n});
}

double cubemap_rect_solid_angle(double u0, double u1, double v0, double v1) {
  return area_element_integral(u1, v1) - area_element_integral(u0, v1) -
         area_element_integral(u1, v0) + area_element_integral(u0, v0);
}

double cubemap_texel_solid_angle(int n, int i, int j) {
  return cubemap_rect_solid_angle(2.0 * i / n - 1.0, 2.0 * (i + 1) / n - 1.0, 2.0 * j / n - 1.0,
                                  2.0 * (j + 1) / n - 1.0);
}

namespace {

std::vector<double> tabulate_solid_angles(int n) {
  // From the (n+1)² corner values of A(u, v): one atan2 per corner, not four per texel (fine
  // grids of sub-texels are tabulated this way for quadratures).
  const auto stride = static_cast<std::size_t>(n) + 1;
  std::vector<double> corner(stride * stride);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      corner[j * stride + i] = area_element_integral(2.0 * i / n - 1.0, 2.0 * j / n - 1.0);
    }
  }
  std::vector<double> omega(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      omega[static_cast<std::size_t>(j) * n + i] =
          corner[(j + 1) * stride + i + 1] - corner[(j + 1) * stride + i] -
          corner[j * stride + i + 1] + corner[j * stride + i];
    }
  }
  return omega;
}

}  // namespace

const std::vector<double>& cubemap_solid_angles(int n) {
  return tabulated<std::vector<double>>(n, [](int k) { return tabulate_solid_angles(k); });
}

CubemapCoord cubemap_coord(Vec3 d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  int face;
  double ma, sc, tc;
  if (ax >= ay && ax >= az) {
    face = d.x >= 0 ? kPosX : kNegX;
    ma = ax;
    sc = d.x >= 0 ? -d.z : d.z;
    tc = -d.y;
  } else if (ay >= az) {
    face = d.y >= 0 ? kPosY : kNegY;
    ma = ay;
    sc = d.x;
    tc = d.y >= 0 ? d.z : -d.z;
  } else {
    face = d.z >= 0 ? kPosZ : kNegZ;
    ma = az;
    sc = d.z >= 0 ? d.x : -d.x;
    tc = -d.y;
  }
  return {face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

CubemapTexel cubemap_texel(int n, Vec3 dir) {
  const CubemapCoord c = cubemap_coord(dir);
  const auto cell = [n](double s) {
    return std::clamp(static_cast<int>(std::floor(s * n)), 0, n - 1);
  };
  return {c.face, cell(c.s), cell(c.t)};
}

std::vector<double> sh_project_cubemap(int order, int n, std::span<const double> texels) {
  return project(order, n, texels);
}

std::vector<Rgb> sh_project_cubemap(int order, int n, std::span<const Rgb> texels) {
  return project(order, n, texels);
}

}  // namespace relight
