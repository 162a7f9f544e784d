// Reconstruction of the incident radiance's SH vector l_p at every vertex p from the adaptive
// near-field samples, Sun 2005 §3.3.5: only samples whose valid domain (a sphere
// of radius r about the sample, §3.3.3) contains p count; they are found through the linear
// octree (sources/emitters/linear_octree.h) and interpolated by Eq. 2.12–2.13 "without the power
// term", i.e. with b = 1: l_p = Σ_i w_i l_i, w_i ∝ 1/‖p − x_i‖. A vertex at a sample's
// position takes that sample alone (the limit of the weights; several coincident samples
// share equally). Sun 2005 says nothing of a vertex that no domain contains: it takes the
// caller's fallback sample (e.g. the one of the BVH leaf holding it).
#pragma once

#include <cstdint>
#include <span>

#include "math/rgb.h"
#include "math/vec3.h"
#include "sources/emitters/incident_sample.h"
#include "sources/emitters/linear_octree.h"

namespace relight {

// The octree over the points to reconstruct (its root from their bounds) with every sample
// inserted by its valid domain; sample ids are indices into `samples`.
LinearOctree build_sample_octree(std::span<const IncidentSample> samples,
                                 std::span<const Vec3> points);

// out[p · k + j] = coefficient j of point p's reconstructed vector, k = the samples' common
// coefficient count (order²); out.size() must be points.size() · k. fallback[p] (an index
// into samples) is used where no valid domain contains point p. Parallel over points.
// Throws std::invalid_argument on inconsistent sizes or a fallback out of range.
void reconstruct_valid_domain(std::span<const IncidentSample> samples, const LinearOctree& octree,
                              std::span<const Vec3> points, std::span<const std::uint32_t> fallback,
                              std::span<Rgb> out);

}  // namespace relight
