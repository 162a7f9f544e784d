// Self-visibility cuts (SVC; issue 15, the capture paper papers/003 §V, Eq. 3–4): at a
// receiving point, V(x, ω) · max(0, n · ω) over the direction tree's leaves — V = 1 where a ray
// from x (pushed off its surface) in direction ω meets nothing of `occluders` — cut by
// math/direction_cut.h at `threshold`. The paper precomputes these at every vertex of every
// object and of the static scene; at render time their product with the other objects'
// visibility cut fields and the environment's cluster values, times the BRDF, summed over the
// cut, gives the outgoing radiance (Eq. 3). Directions below the surface have value 0 and are
// not traced. Pinned by tests/sources/cuts/self_visibility_test.cpp.
#pragma once

#include <cstdint>

#include "math/direction_cut.h"
#include "math/direction_tree.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

// The SVC at point p (on its surface) with unit normal n; `rays` counts the rays traced.
DirectionCut self_visibility_cut(const Occluders& occluders, const DirectionTree& tree, Vec3 p,
                                 Vec3 n, double threshold, std::uint64_t& rays);

}  // namespace relight
