// Frosted glass on a portal (Yue et al. 2009 §1, §5: "The material of the portals
// can also be modified at run time (e.g. changing from transparent glass to frosted glass)";
// "the environmental light distribution is then modified according to the change in the
// material of the portal"): a blur of the shell's radiance cubemap that keeps the flux through
// the window exactly.
//
// In the portal frame, with c(ω) = max(0, ω·outward) and Ω(ω) the texel's solid angle, for the
// texels in front of the window (c > 0 at the texel centre) the light arriving from ω is
// scattered into the front texels in proportion to K(ω, ω')·c(ω')·Ω(ω'):
//     L'(ω') = Σ_ω L(ω)·c(ω)·Ω(ω)·K(ω, ω') / Z(ω),   Z(ω) = Σ_{ω': c>0} K(ω, ω')·c(ω')·Ω(ω'),
// so Σ L'·c·Ω = Σ L·c·Ω over the front texels (the flux through a window of unit area, up to
// rounding). K is the von Mises–Fisher kernel K = exp((ω·ω' − 1)/σ²), σ = frost_deg in
// radians. Meaning of frost_deg: for small widths K ≈ exp(−θ²/(2σ²)), θ the angle between ω
// and ω', a Gaussian whose standard deviation along any one angular axis is frost_deg (the RMS
// angular radius of the spread is √2·frost_deg); 0 means clear glass (identity). Texels behind
// the window plane (c ≤ 0) keep their values. Not uniform-preserving near the window plane (a
// uniform L turns into Σ_ω L·c·Ω·K/Z, which dips toward grazing directions): flux is what
// frosting conserves, not radiance.
//
// Cost: the kernel is truncated where K < e^−36 ≈ 2·10⁻¹⁶ and rounded to float (the same
// truncated, rounded K enters Z, so the flux identity holds to double rounding); front texels
// are grouped in 4×4 tiles whose bounding cones cull far tile pairs. K and Z depend only on
// (N, outward, frost_deg): a FrostPlan holds them (K as float, up to 64 MiB: every frost width
// at N = 32) and is reused while those stay (the usual case: the sky changes, the glass does
// not); each application is then one sparse matrix–vector product, parallel over tiles
// (oneTBB). Measured figures: bench/shell_bench.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

struct FrostPlan {
  int face_size = 0;
  Vec3 outward;
  double frost_deg = 0;
  double inv_sigma2 = 0;  // 1/σ²
  double min_dot = 1;     // pairs with ω·ω' < min_dot have K below the cut-off
  // Front texels grouped by tile: cubemap index, direction (SoA), c·Ω and 1/Z.
  std::vector<std::uint32_t> texel;
  std::vector<double> x, y, z, weight, inv_z;
  std::vector<std::uint32_t> tile_begin;       // tiles' ranges in the texel arrays (+1 entry)
  std::vector<std::uint32_t> neighbour_begin;  // per tile: range in `neighbour` (+1 entry)
  std::vector<std::uint32_t> neighbour;        // tiles within reach of each tile (itself too)
  // K per (front texel i, texel j of the tiles within reach of i's tile), rows in tile order;
  // tile p's rows start at kernel_begin[p]. Empty when over the storage budget (then K is
  // recomputed, to the same values, at each application).
  std::vector<std::size_t> kernel_begin;
  std::vector<float> kernel;
};

// Whether `plan` was made for these arguments (then make_frost_plan need not run again).
bool frost_plan_matches(const FrostPlan& plan, int face_size, Vec3 outward, double frost_deg);

// Kernel values a plan stores by default (float): 2^24 = 64 MiB. N = 32 needs at most
// 3072² ≈ 9.4 M (a frost wide enough to reach the whole front hemisphere); N = 64 beyond ~5°
// does not fit and is recomputed at each application.
inline constexpr std::size_t kFrostMaxStoredKernel = std::size_t{1} << 24;

// Fills `plan` (reusing its storage). outward need not be unit (non-zero, finite); frost_deg
// finite and ≥ 0 (0: an empty plan, apply_frost does nothing). The kernel is stored when it
// has at most max_stored_kernel values. std::invalid_argument for bad arguments.
void make_frost_plan(int face_size, Vec3 outward, double frost_deg, FrostPlan& plan,
                     std::size_t max_stored_kernel = kFrostMaxStoredKernel);

// Blurs the front texels of `cubemap` (6·N² texels, math/cubemap.h layout) in place; scratch is
// resized as needed (reused between calls).
void apply_frost(const FrostPlan& plan, std::span<Rgb> cubemap, std::vector<Rgb>& scratch);

// One-shot: plan and apply.
void frost_cubemap(int face_size, Vec3 outward, double frost_deg, std::span<Rgb> cubemap);

}  // namespace relight
