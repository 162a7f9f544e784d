// `relight capture`: two fisheye brackets → one calibrated HDR environment map (the illumination
// capture of Hao et al. 2020, §IV, paper 003, with its hand work automated).
//
// Steps, each in its own file: the brackets and their exposures (bracket.h); each view's
// image circle (image_circle.h); the camera response and the HDR merge (camera_response.h);
// each view onto the equirectangular map (fisheye_view.h, view_map.h); the lens frame's band
// and what stood in one view removed, the views blended (view_blend.h, outliers.h); what no
// view saw filled (poisson_fill.h); the absolute scale (below).
//
// Calibration: with a lux-meter reading E at the camera facing up, the map is scaled so that
// its horizontal illuminance Σ Y(d) max(0, d_y) Ω equals E, making it cd/m²; without one the
// values stay relative (X(128) = 1 at one unit of exposure, bracket.h) and the result says so.
// Pixels clipped even in the shortest exposure hold only a lower bound; their share of the
// horizontal illuminance is reported as a warning. With a reading, the flux they miss is given
// to them when every photo of both brackets records ISO and f-number: the exposures are then
// photographic and the reflected-light meter equation fixes the unclipped texels at
// kPhotographicLuminance (bracket.h) per unit; the clipped texels are multiplied by the one
// common factor that makes the total equal the reading. Without that EXIF (or when the
// estimate leaves nothing missing) the whole map is scaled, which puts the clipped flux's
// deficit on every texel (docs/capture.md). Pinned by tests/capture/capture_test.cpp (the whole
// capture, end to end, on a synthetic one).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "capture/camera_response.h"
#include "capture/fisheye_view.h"
#include "image/image.h"
#include "light/environment.h"

namespace relight {

struct CaptureOptions {
  std::vector<std::filesystem::path> front, back;
  // Seconds, in file order: one per photo of both brackets (front first), or one list that
  // both brackets share. Empty: EXIF.
  std::vector<double> exposure_times;
  FisheyeLens lens;
  int width = 1024;
  std::optional<double> illuminance_lux;
};

struct CapturedView {
  ImageCircle circle;
  double clean_limit_deg = 0;  // off-axis angle up to which the view is used
  Image merged;                // the merged photo, relative radiance (for --debug)
};

struct CaptureResult {
  EquirectMap map;  // cd/m² when calibrated, else relative radiance
  bool calibrated = false;
  double scale = 1;                   // applied to the merged values
  double horizontal_illuminance = 0;  // of the map as written (lx when calibrated)
  double clipped_share = 0;           // share of it through clipped texels (a lower bound)
  double removed_sr = 0;              // solid angle removed as outliers
  double filled_sr = 0;               // solid angle filled (holes and outliers)
  CapturedView front, back;
  CameraResponse response;  // the camera's, shared by both brackets
  // Map-sized masks for --debug: 0 room, 1 hole (no view), 2 outlier, 3 clipped.
  std::vector<std::uint8_t> mask;
  std::vector<std::string> warnings;
};

// Throws InputError naming the file or option and the reason for bad input.
CaptureResult capture_environment(const CaptureOptions& options);

// Σ Y(d) max(0, d_y) Ω over the map: the illuminance on an upward-facing plane at its centre.
double map_horizontal_illuminance(const EquirectMap& map);

}  // namespace relight
