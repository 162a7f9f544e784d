// The environment part of a portal's shell (Yue et al. 2009 §3, §5: the shell is
// "an environment light source" whose radiance is re-captured at every state change), split
// into what the exterior renderer (light/exterior_objects.h) needs separately:
//  * the continuous part — a copy of the Environment without its sun disc (only a sky has one:
//    light/environment.h; a map carries any sun in its texels, a uniform environment none). The
//    ground of the copy keeps its luminance, which already includes the sun's contribution
//    (light/sky_model.h), since only the disc is removed;
//  * the sun disc, deposited into the cubemap exactly as environment_cubemap does it: its
//    ∫ L dω divided by the solid angle of the texel containing its centre, so Σ L·Ω keeps the
//    sun's energy. environment_cubemap(continuous) + deposit == environment_cubemap(env).
//  * the irradiance of the continuous part on a plane of any orientation, for shading exterior
//    surfaces: Ramamoorthi & Hanrahan 2001 ("An Efficient Representation for Irradiance
//    Environment Maps", Eq. 8-9): E(n) = Σ_l Â_l Σ_m c_lm Y_lm(n), the clamped-cosine kernel's
//    band factors Â_0 = π, Â_1 = 2π/3, Â_2 = π/4 on the environment's SH of l ≤ 2 (9
//    coefficients; the kernel's higher even bands are ≤ π/24, and the R&H error bound for
//    l ≤ 2 is ~3 % of the mean irradiance, exact for a uniform environment). The sun is left
//    out here and shaded exactly (E_sun·max(0, n·s)) by the caller.
// The portals' shells and the reference tracer's exterior objects share these views of an
// Environment.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "light/environment.h"
#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

// The environment without its sun disc (a copy; the same environment for maps and uniform).
Environment environment_without_sun(const Environment& env);

// What deposit_sun added: the radiance, to the texel at index `texel`.
struct SunDeposit {
  std::size_t texel = 0;
  double radiance = 0;
};

// Adds the disc's ∫ L dω / Ω_texel (every channel; the sun is grey) to the texel containing its
// centre; cubemap holds 6·N² texels (math/cubemap.h layout).
SunDeposit deposit_sun(const SunDisc& sun, int face_size, std::span<Rgb> cubemap);

// Irradiance E(n) on a plane of unit normal n from an environment's l ≤ 2 SH (Ramamoorthi &
// Hanrahan 2001).
struct IrradianceSh {
  std::array<Rgb, 9> coeffs{};  // Â_l·c_lm, index sh_index(l, m) of math/sh.h
  Rgb irradiance(Vec3 n) const;
};
// From SH coefficients of order >= 3 (extra bands are ignored).
IrradianceSh irradiance_sh(std::span<const Rgb> environment_coeffs);
// From the environment's own SH projection (light/environment.h environment_sh, order 3).
IrradianceSh irradiance_sh(const Environment& env);

}  // namespace relight
