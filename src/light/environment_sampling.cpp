#include "light/environment_sampling.h"

#include <algorithm>
#include <cmath>

#include "math/equirect.h"
#include "math/rgb.h"

namespace relight {

namespace {

constexpr int kSkyGridWidth = 256;
constexpr double kFloor = 0.01;  // of the mean texel weight, for grids of point values

// The index of the interval of `cdf` (ascending, from 0 to 1) that holds u.
std::size_t interval(const double* cdf, std::size_t count, double u) {
  const double* at = std::upper_bound(cdf, cdf + count + 1, u);
  return static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(at - cdf - 1, 0, static_cast<std::ptrdiff_t>(count) - 1));
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const Environment& env) {
  const bool map = env.kind == EnvironmentKind::kMap && env.map && env.map->width > 0;
  width_ = map ? env.map->width : kSkyGridWidth;
  height_ = map ? env.map->height : kSkyGridWidth / 2;
  if (map) rotation_ = MapRotation(env.rotate_deg);
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  weight_.assign(w * h, 0.0);
  for (std::size_t j = 0; j < h; ++j) {
    const double omega = equirect_row_solid_angle(width_, height_, static_cast<int>(j));
    for (std::size_t i = 0; i < w; ++i) {
      const Rgb l = map ? env.map->texels[j * w + i]
                        : env.diffuse_radiance(equirect_texel_direction(
                              width_, height_, static_cast<int>(i), static_cast<int>(j)));
      weight_[j * w + i] = std::max(0.0, luminance(l)) * omega;
    }
  }
  double sum = 0;
  for (const double x : weight_) sum += x;
  if (!(sum > 0)) return;
  if (!map) {  // point values of a continuous function: keep every direction drawable
    for (std::size_t j = 0; j < h; ++j) {
      const double omega = equirect_row_solid_angle(width_, height_, static_cast<int>(j));
      for (std::size_t i = 0; i < w; ++i) weight_[j * w + i] += kFloor * sum / (4 * kPi) * omega;
    }
    sum *= 1 + kFloor;
  }
  total_ = sum;
  for (double& x : weight_) x /= sum;
  row_cdf_.assign(h + 1, 0.0);
  texel_cdf_.assign(h * (w + 1), 0.0);
  for (std::size_t j = 0; j < h; ++j) {
    double row = 0;
    for (std::size_t i = 0; i < w; ++i) {
      row += weight_[j * w + i];
      texel_cdf_[j * (w + 1) + i + 1] = row;
    }
    for (std::size_t i = 1; i <= w; ++i) {
      texel_cdf_[j * (w + 1) + i] = row > 0 ? texel_cdf_[j * (w + 1) + i] / row : 1.0;
    }
    row_cdf_[j + 1] = row_cdf_[j] + row;
  }
  for (double& x : row_cdf_) x /= row_cdf_.back();
}

EnvironmentSampler::Sample EnvironmentSampler::sample(double u1, double u2) const {
  if (empty()) return {};
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  const std::size_t j = interval(row_cdf_.data(), h, u1);
  // Reuse u1 within the row's interval for the column, u2 for the point in the texel.
  const double row_width = row_cdf_[j + 1] - row_cdf_[j];
  const double t = row_width > 0 ? std::clamp((u1 - row_cdf_[j]) / row_width, 0.0, 1.0) : 0.5;
  const double* cdf = &texel_cdf_[j * (w + 1)];
  const std::size_t i = interval(cdf, w, t);
  const double cell = cdf[i + 1] - cdf[i];
  const double s = cell > 0 ? std::clamp((t - cdf[i]) / cell, 0.0, 1.0) : 0.5;
  // Uniform in φ and cos θ within texel (i, j).
  const double u = (static_cast<double>(i) + s) / width_;
  const double cos_top = std::cos(kPi * static_cast<double>(j) / height_);
  const double cos_bottom = std::cos(kPi * static_cast<double>(j + 1) / height_);
  const double cos_theta = cos_top + u2 * (cos_bottom - cos_top);
  const double v = std::acos(std::clamp(cos_theta, -1.0, 1.0)) / kPi;
  const Vec3 dir = rotation_.to_world(equirect_direction(u, v));
  const double omega = equirect_row_solid_angle(width_, height_, static_cast<int>(j));
  return {dir, weight_[j * w + i] / omega};
}

double EnvironmentSampler::pdf(Vec3 dir) const {
  if (empty()) return 0;
  const EquirectTexel t = equirect_texel(width_, height_, rotation_.to_map(dir));
  return weight_[static_cast<std::size_t>(t.j) * static_cast<std::size_t>(width_) +
                 static_cast<std::size_t>(t.i)] /
         equirect_row_solid_angle(width_, height_, t.j);
}

}  // namespace relight
