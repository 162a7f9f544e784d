// Sample positions of Sun 2005's near-field baseline (§2.2.5 and Ch. 4): Sloan et
// al. [SKS02] place the incident-radiance samples over an object's vertices with the LBG
// vector quantiser of Linde, Buzo and Gray [LBG80] (Sun 2005 calls it "ICP"). Starting from
// the centroid, every codeword is split into two (±1e-3 of the bounds' diagonal along a
// pseudo-random direction) and Lloyd iterations follow: each point to its nearest codeword
// (ties to the lower index), each codeword to its cluster's mean (an empty cluster's codeword
// stays), until the distortion Σ‖p − c(p)‖² changes by less than 1e-4 of itself, the
// assignment no longer changes, or 50 iterations. The last split of a count that is not a
// power of two splits only the codewords whose clusters had the largest distortion.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

// `count` codewords for the points (none for count <= 0), deterministic for a seed. The
// returned codewords are the means of the clusters of the last assignment. The assignment
// step is parallel (a k-d tree over the codewords). Throws std::invalid_argument when there
// are no points but codewords are asked for.
std::vector<Vec3> lbg_sample_positions(std::span<const Vec3> points, int count, std::uint64_t seed);

}  // namespace relight
