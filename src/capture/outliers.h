// Outlier detection on a blended map (capture/capture.h): what stood in one view only — the
// photographer beside the camera, a tripod leg — which no cross-check can catch because the
// other view never saw those directions.
//
// Such a thing stands near the camera and reaches down toward the floor beneath it, so it is
// looked for below the horizon, as a region much darker than its surroundings: the map's ln
// luminance against its running median over a window 90° wide (wide enough that a person does not
// pull it down) (OpenCV medianBlur on ln Y quantised to 1/256 of its 0.5–99.5 % range), texels more
// than ln 3 below it (a third of their surroundings), grouped into opened by a 2° disc (cutting
// thin bridges to dark furniture behind a person), grouped into 8-connected regions. A region is an
// outlier when it covers at least 0.02 sr (about 8° × 8°), its mean elevation is −35° or lower and
// it reaches −65° or lower: someone crouching or standing within about half a metre of a camera
// held 1.2 m up (their feet are that far below the horizon), a tripod's legs. It grows by 2° to
// take its soft edge. A person further away is not caught (docs/capture.md). Dark furniture near
// the horizon (a television, a door, a wardrobe) and small dark things stay: they are the room.
// Pinned by tests/capture/capture_test.cpp (the photographer's directions, the planes and the
// grid, which a false detection of the room's dark furniture would break).
#pragma once

#include <cstdint>
#include <vector>

#include "capture/view_blend.h"

namespace relight {

// 1 for each texel of an outlier region (holes of the map are never outliers).
std::vector<std::uint8_t> find_outliers(const BlendedMap& map);

}  // namespace relight
