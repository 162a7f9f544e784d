// Two views into one map, with what is not the room removed (capture/capture.h).
//
// 1. The lens frame's reflection: a dark ring just inside each image circle. Where the views
//    overlap (a 190° lens leaves a 10° ring seen by both) each view is compared with the
//    other: the median of ln(Y_view / Y_other) in 0.25° rings of the view's off-axis angle θ.
//    Walking in from the rim, rings where the view reads darker than the other by more than
//    20 % are its frame band; the view is used only inside the band's inner edge (less 0.5°),
//    its *clean limit*. Medians ignore what covers only part of a ring (a photographer).
// 2. Blending: each view's weight falls smoothly (smoothstep) from 1 to 0 over the last 2° of
//    its clean limit, and the map is the weighted mean. Where both views see a texel but
//    disagree by more than a factor 1.5, something stood in one of them (the photographer
//    behind the camera appears at the rim of a view, the other saw the room there): the view
//    nearer its own axis is kept alone.
// 3. What no view saw cleanly is a hole, filled later (poisson_fill.h).
// Pinned by tests/capture/capture_test.cpp (TheLensFrameBandIsCutFromEachView, the planes).
#pragma once

#include <cstdint>
#include <vector>

#include "capture/view_map.h"

namespace relight {

// The off-axis angle (rad) up to which `view` agrees with `other` (step 1); half_fov when no
// band is found.
double clean_limit(const ViewMap& view, const ViewMap& other, double half_fov);

struct BlendedMap {
  int width = 0, height = 0;
  std::vector<Rgb> radiance;
  std::vector<std::uint8_t> hole;     // no view saw the texel cleanly
  std::vector<std::uint8_t> clipped;  // a clipped pixel contributes
};

BlendedMap blend_views(const ViewMap& front, double front_limit, const ViewMap& back,
                       double back_limit);

}  // namespace relight
