// One fisheye view resampled onto the equirectangular map (capture/capture.h), in the
// math/equirect.h orientation of `{"type": "map"}` environments.
//
// The merged photo is first reduced by area averaging (OpenCV INTER_AREA) until it has about
// two pixels per map texel at the circle's centre, so that no texel aliases; each texel is
// then the mean of 3 × 3 bilinear samples at points spread over it. A texel whose samples do
// not all fall inside the field of view is unseen by the view.
// Pinned by tests/capture/capture_test.cpp (the planes and the 32 × 16 grid against the truth).
#pragma once

#include <cstdint>
#include <vector>

#include "capture/camera_response.h"
#include "capture/fisheye_view.h"

namespace relight {

struct ViewMap {
  int width = 0, height = 0;
  std::vector<Rgb> radiance;          // relative radiance; 0 where unseen
  std::vector<float> theta;           // off-axis angle of the texel centre (rad)
  std::vector<std::uint8_t> seen;     // 1 where the view covers the whole texel
  std::vector<std::uint8_t> clipped;  // 1 where a clipped pixel contributes
};

ViewMap project_view(const HdrPhoto& photo, const FisheyeView& view, int width);

}  // namespace relight
