// Equirectangular map mapping, row solid angles and SH projection; see equirect.h.
#include "math/equirect.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "math/sh.h"

namespace relight {
namespace {

template <class T>
std::vector<T> project(int order, int width, int height, std::span<const T> texels) {
  assert(texels.size() == static_cast<std::size_t>(width) * height);
  std::vector<T> c(sh_count(order));
  for (int j = 0; j < height; ++j) {
    const double omega = equirect_row_solid_angle(width, height, j);
    for (int i = 0; i < width; ++i) {
      sh_add_sample(equirect_texel_direction(width, height, i, j),
                    texels[static_cast<std::size_t>(j) * width + i] * omega, std::span<T>(c));
    }
  }
  return c;
}

}  // namespace

Vec3 equirect_direction(double u, double v) {
  const double theta = kPi * v, phi = 2.0 * kPi * u;
  const double st = std::sin(theta);
  return {st * std::sin(phi), std::cos(theta), -st * std::cos(phi)};
}

EquirectUv equirect_uv(Vec3 d) {
  const double len = length(d);
  const double theta = std::acos(std::clamp(d.y / len, -1.0, 1.0));
  double phi = std::atan2(d.x, -d.z);
  if (phi < 0) phi += 2.0 * kPi;
  double u = phi / (2.0 * kPi);
  if (u >= 1.0) u = 0.0;
  return {u, theta / kPi};
}

Vec3 equirect_texel_direction(int width, int height, int i, int j) {
  return equirect_direction((i + 0.5) / width, (j + 0.5) / height);
}

EquirectTexel equirect_texel(int width, int height, Vec3 dir) {
  const EquirectUv uv = equirect_uv(dir);
  return {std::clamp(static_cast<int>(std::floor(uv.u * width)), 0, width - 1),
          std::clamp(static_cast<int>(std::floor(uv.v * height)), 0, height - 1)};
}

double equirect_row_solid_angle(int width, int height, int j) {
  return 2.0 * kPi / width * (std::cos(kPi * j / height) - std::cos(kPi * (j + 1) / height));
}

std::vector<double> sh_project_equirect(int order, int width, int height,
                                        std::span<const double> texels) {
  return project(order, width, height, texels);
}

std::vector<Rgb> sh_project_equirect(int order, int width, int height,
                                     std::span<const Rgb> texels) {
  return project(order, width, height, texels);
}

}  // namespace relight
