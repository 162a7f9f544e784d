// The environment part of a portal shell: sun-less copy, sun deposit, R&H irradiance; see
// light/environment_irradiance.h.
#include "light/environment_irradiance.h"

#include <stdexcept>

#include "math/cubemap.h"
#include "math/sh.h"

namespace relight {

Environment environment_without_sun(const Environment& env) {
  Environment out = env;
  if (out.kind == EnvironmentKind::kSky) out.sky.sun.reset();
  return out;
}

SunDeposit deposit_sun(const SunDisc& sun, int face_size, std::span<Rgb> cubemap) {
  if (face_size < 1 || cubemap.size() != cubemap_texel_count(face_size))
    throw std::invalid_argument("deposit_sun: cubemap must hold 6·N² texels");
  const CubemapTexel t = cubemap_texel(face_size, sun.direction);
  const double l = sun.integrated_luminance() / cubemap_texel_solid_angle(face_size, t.i, t.j);
  const std::size_t texel = cubemap_texel_index(face_size, t);
  cubemap[texel] += Rgb{l, l, l};
  return {texel, l};
}

Rgb IrradianceSh::irradiance(Vec3 n) const {
  std::array<double, 9> y{};
  sh_eval(3, n, y);
  Rgb e;
  for (int k = 0; k < 9; ++k) e += coeffs[k] * y[k];
  return e;
}

IrradianceSh irradiance_sh(std::span<const Rgb> environment_coeffs) {
  if (environment_coeffs.size() < 9)
    throw std::invalid_argument("irradiance_sh: needs SH of order >= 3");
  // Clamped-cosine band factors (R&H 2001 Eq. 8-9).
  constexpr double kA[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};
  IrradianceSh out;
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m)
      out.coeffs[sh_index(l, m)] = environment_coeffs[sh_index(l, m)] * kA[l];
  return out;
}

IrradianceSh irradiance_sh(const Environment& env) {
  return irradiance_sh(environment_sh(env, 3));
}

}  // namespace relight
