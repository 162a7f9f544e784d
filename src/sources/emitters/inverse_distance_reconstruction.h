// The near-field baseline of Sun 2005 (§2.2.5, after Sloan et al. [SKS02] and
// Annen et al. [AKDS04]): the incident radiance's SH vector at a point p interpolated from ALL
// samples, Eq. 2.12–2.13: l_p = Σ_i w_i l_i with w_i = ‖p − x_i‖^−b / Σ_j ‖p − x_j‖^−b. The
// samples' valid domains are ignored (the ICP baseline has none). A point at a sample's
// position takes that sample alone (the limit of the weights; several coincident samples share
// equally). Sun 2005's comparison uses it with the ICP/LBG positions (lbg_placement.h).
#pragma once

#include <span>

#include "math/rgb.h"
#include "math/vec3.h"
#include "sources/emitters/incident_sample.h"

namespace relight {

// out[p · k + j] = coefficient j of point p's reconstructed vector, k = the samples' common
// coefficient count (order²); out.size() must be points.size() · k. exponent = b >= 0.
// Parallel over points; costs points × samples × k. Throws std::invalid_argument on
// inconsistent sizes, no samples (with points) or a bad exponent.
void reconstruct_inverse_distance(std::span<const IncidentSample> samples,
                                  std::span<const Vec3> points, std::span<Rgb> out,
                                  double exponent = 2.0);

}  // namespace relight
