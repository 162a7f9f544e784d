// Per-receiver SH transfer vectors with self-shadowing for near-field lighting (Sun 2005
// §3.2.1, Algorithm 3.1 and 3.2; Sloan et al. 2002's diffuse shadowed transfer):
//   t_k(p) = ∫_S² V(p, ω) max(0, n_p · ω) Y_k(ω) dω,   k < order²,
// in the world frame (no rotation at run time), so that the irradiance at p under incident
// radiance with SH coefficients l_k is E(p) = Σ_k t_k l_k (and the radiance a diffuse surface
// of albedo ρ sends is ρE/π). Estimated by stratified uniform directions over the sphere
// (Algorithm 3.2: a jittered √N × √N grid in (cos θ, φ)), each of weight 4π/N, one visibility
// ray each towards the upper hemisphere, up to max_distance: self-shadowing is the receivers'
// own neighbourhood (Sun 2005 shades an object in the open; inside a room the walls would
// block every distant direction while the emitters are inside).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/ranks.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

struct NearfieldTransferSettings {
  int order = 4;             // SH bands l < order (Sun 2005: 16 coefficients)
  int sqrt_directions = 16;  // √N: N = 256 directions per receiver
  // Occluders farther than this (m) do not shadow: a room's walls would otherwise hide every
  // direction, while near-field emitters shine from inside the room (see PrecomputeSettings).
  double max_distance = std::numeric_limits<double>::infinity();
  std::uint64_t seed = 1;
};

// receivers × order² floats, receiver-major. `occluders` is the static scene. With several
// `ranks` (engine/ranks.h), this process traces its share's rows and keeps only those (the
// others zero): rank 0 gathers them as it writes the file.
std::vector<float> nearfield_transfer(const RayTracer& occluders, std::span<const Vec3> positions,
                                      std::span<const Vec3> normals,
                                      const NearfieldTransferSettings& settings,
                                      const RankShares* ranks = nullptr);

}  // namespace relight
