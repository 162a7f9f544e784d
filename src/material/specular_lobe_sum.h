// The glTF metallic–roughness BRDF's specular lobe (material/metallic_roughness.h) summed over many
// lights toward one eye, eight lights at a time in single precision (the glossy view of the capture
// paper, papers/003 §V.B, Eq. 3 — per vertex Σ over its cut's nodes of the node's light times the
// BRDF toward the eye; the view's frame is this sum at ~1,500 nodes of each glossy vertex).
//
// Lights are given by their first moments, so that the irradiance is found in the same pass:
// light k gives a surface of unit normal n the irradiance e_c = n · M_c[k] in channel c, from
// the unit direction l_k (light/environment_clusters.h's RgbMoment and moment_direction, in
// planes of floats: MomentLightPlanes). The sum is
//     Σ_k w_k · e_k · F(v·h) D(n·h) V(n·l, n·v)   over lights with n·l_k > 0 and some e_c > 0,
// exactly which lights and which terms MetallicRoughnessToward::specular sums one at a time
// (sources/environment/environment_lighting.h for_each_light), rearranged for float:
//     v·h = √((1 + v·l) / 2),  |l + v|² = 2 (1 + v·l),
//     D V = α² / (2π) · |l + v|⁴ / (S² · (n·l Λ_v + n·v Λ_l)),
//     S = |n × (l + v)|² + (n·(l + v))² α²,  Λ_x = √(α² + (1 − α²)(n·x)²),
// S being |l + v|² ((n·h)² (α² − 1) + 1) with 1 − (n·h)² taken as |n × h|², which keeps a
// smooth lobe's peak (α² down to 1e-8) in single precision, where 1 − (n·h)² would cancel.
// One division and two square roots a light; AVX2 and FMA where the processor has them, the
// same arithmetic one light at a time otherwise. Pinned by
// tests/material/specular_lobe_sum_test.cpp (both paths against the double-precision lobe to
// 1e-5 + 6e-8/α — a float's rounding of a direction against the lobe's width — roughness
// 0.01–1, grazing eyes, lights below the surface and of negative channels) and
// tests/render/glossy_view_test.cpp (a view's sums against the lobe node by node).
#pragma once

#include <array>
#include <cstddef>

#include "material/metallic_roughness.h"
#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

// Twelve planes of floats, one entry a light: M_r (x, y, z), M_g (x, y, z), M_b (x, y, z),
// then l (x, y, z).
struct MomentLightPlanes {
  std::array<const float*, 12> plane{};
};

// Up to kCapacity lights kept in place (a vertex's odd nodes while its cut is walked).
class MomentLightBatch {
 public:
  static constexpr std::size_t kCapacity = 64;
  bool full() const { return size_ == kCapacity; }
  std::size_t size() const { return size_; }
  void clear() { size_ = 0; }
  // Appends a light of moments `m` (9 floats, as the planes) scaled by `weight`, from `l`.
  void push(const float* m, Vec3 l, float weight);
  MomentLightPlanes planes() const;

 private:
  std::array<std::array<float, kCapacity>, 12> plane_{};
  std::size_t size_ = 0;
};

class SpecularLobeSum {
 public:
  // kPortable: one light at a time even where AVX2 runs (the tests compare both paths).
  enum class Path { kFastest, kPortable };
  // Sums `brdf`'s specular lobe (its normal, viewer, F0 and α); 0 when the viewer is below it.
  explicit SpecularLobeSum(const MetallicRoughnessToward& brdf, Path path = Path::kFastest);
  // Adds weight · Σ over lights [begin, end) of `lights`.
  void add(const MomentLightPlanes& lights, std::size_t begin, std::size_t end, float weight);
  void add(const MomentLightBatch& batch, float weight) {
    add(batch.planes(), 0, batch.size(), weight);
  }
  // Adds one light of moments `m` (the planes' nine floats) from `l`, kept with others until
  // eight or more can be summed together.
  void add_one(const std::array<float, 9>& m, Vec3 l) {
    pending_.push(m.data(), l, 1);
    if (pending_.full()) flush_pending();
  }
  // The sum so far (the lights kept by add_one summed first).
  Rgb total();

  // The lobe's constants in single precision, shared by both paths.
  struct Lobe {
    float nx, ny, nz, vx, vy, vz, n_dot_v, masking_v, alpha2, one_minus_alpha2, scale;
    std::array<float, 3> f0;
  };

 private:
  Lobe lobe_{};
  bool lit_ = false;  // the viewer above the surface
  bool avx2_ = false;
  std::array<std::array<float, 8>, 3> acc_{};
  void flush_pending();
  MomentLightBatch pending_;  // add_one's lights
};

}  // namespace relight
