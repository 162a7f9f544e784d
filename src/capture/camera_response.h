// The camera's response and the HDR merge of a bracket (capture/capture.h): Debevec & Malik,
// "Recovering High Dynamic Range Radiance Maps from Photographs" (SIGGRAPH 1997).
//
// Response: for 8-bit photos, the inverse response X(z) (relative exposure that gives pixel
// value z, per channel) is recovered by OpenCV's CalibrateDebevec (photo module, smoothness
// λ = 30) from 144 flat pixels of each image circle, a third spread evenly over each channel's
// log radiance (camera_response.cpp, sample_offsets). Both brackets are one system when their
// exposure ratios match (side by side in one sample image per shot). OpenCV fixes g(128) = 0,
// so X(128) = 1 in every channel: mid-grey keeps the camera's white balance. 16-bit photos (a
// phone's linear "raw-like" TIFF or PNG) are taken as linear: X(z) = z / 32768.
//
// Merge: Debevec & Malik Eq. 6, the weighted mean of ln X(z) − ln Δt over the shots with
// the hat weight w(z) = min(z, zmax − z), and w = 0 from 98 % of full scale up (a saturated
// shot only says "at least"; even a small weight would pull bright pixels down by tens of
// per cent). A channel at or above 98 % of full scale in the shortest shot is *clipped*: its
// value is the lower bound X(z)/Δt of that shot, and the pixel is flagged. A channel black
// in every shot takes the longest shot's value.
// Pinned by tests/capture/capture_test.cpp (the response within 3.3 % of the true curve over
// z = 16..240; 16-bit linear PNGs).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "capture/bracket.h"
#include "capture/image_circle.h"
#include "math/rgb.h"

namespace relight {

struct CameraResponse {
  // exposure[c][z]: relative exposure of pixel value z in channel c (R, G, B), increasing.
  std::array<std::vector<double>, 3> exposure;
  bool linear = false;  // 16-bit photos: X(z) = z / 32768
};

// The camera's response, from the pixels inside the brackets' image circles (one circle per
// bracket). Brackets with the same exposure ratios are solved as one system (a view that never
// exposes its brightest values still gets the whole curve from the other); otherwise the
// bracket whose samples span the most grey values is used for all.
CameraResponse recover_response(std::span<const Bracket* const> brackets,
                                std::span<const ImageCircle> circles);

// A merged view: relative radiance per pixel (row-major, top row first) and the clipped flags.
struct HdrPhoto {
  int width = 0, height = 0;
  std::vector<Rgb> radiance;
  std::vector<std::uint8_t> clipped;  // 1 where a channel saturates in the shortest shot
};

HdrPhoto merge_bracket(const Bracket& bracket, const CameraResponse& response);

}  // namespace relight
