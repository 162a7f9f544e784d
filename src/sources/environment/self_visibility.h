// Self-visibility cuts (SVC; Iwasaki et al., Cyberworlds, §V, Eq. 3–4: the capture paper,
// papers/003): at a receiving point x of unit normal n, the visibility V(x, ω) over the direction
// tree's leaves — 1 where a ray from x in direction ω meets nothing of `occluders` and n · ω > 0,
// else 0 — cut by math/direction_cut.h at `threshold`. The paper clusters V · cos; we cluster V
// alone and bring the cosine in through the environment's first moment over each node
// (light/environment_clusters.h: Σ_k V_k · n · ∫_k L ω dω), which is exact on every node whose
// leaves agree. So V stays binary, a node is merged only where its leaves agree (threshold 0, the
// paper's rule for its visibility cut fields; a threshold below ½ lets a node's disagreeing
// minority of at most that fraction go), its edges stay as sharp as the leaves, and a node takes 5
// bits (math/cut_encoding.h). Measured against V · cos at 32,768 directions (docs/decisions.md):
// the L∞ threshold that keeps V · cos's error within 2 % leaves 17 kB a floor point and misplaces a
// sun's 45° cosine by up to 2.8 %. Directions below the surface are not traced. Pinned by
// tests/sources/environment/self_visibility_test.cpp.
#pragma once

#include <cstdint>

#include "math/direction_cut.h"
#include "math/direction_tree.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

// The SVC of a surface point of unit normal n whose rays start at `origin` (pushed off the
// surface by trace/ray_tracer.h offset_from_surface); `rays` counts the rays traced.
DirectionCut self_visibility_cut(const Occluders& occluders, const DirectionTree& tree, Vec3 origin,
                                 Vec3 n, double threshold, std::uint64_t& rays);

}  // namespace relight
