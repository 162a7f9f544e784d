// One auto-exposure bracket (the capture of Hao et al. 2020, §IV, paper 003): the photos of one
// fisheye view, taken from one point, and each one's exposure. When every shot records ISO S and
// f-number N, a shot's exposure is the photographic one, t · (S/100) / N² (the sensor's signal is
// proportional to t · S / N²; ISO 100 at f/1 as the unit), so shots and brackets taken at different
// ISO or aperture share one scale, and a merged value v = 1 (mid-grey, X(128) = 1) is the luminance
// K/100 · v by the reflected-light meter equation L = K N²/(t S) (ISO 2720, K = 12.5 cd·s/m²).
// Otherwise it is the exposure time t.
// Pinned by tests/capture/bracket_test.cpp.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "image/photo.h"

namespace relight {

struct Bracket {
  std::string name;  // "front" or "back": how messages name the bracket
  std::vector<std::filesystem::path> files;
  std::vector<Photo> shots;
  std::vector<PhotoExposure> exif;     // per shot, the time from --exposure-times when given
  std::vector<double> exposures;       // per shot: t · (S/100) / N², or t (see above)
  bool photographic_exposure = false;  // every shot records ISO and f-number
};

// K/100: cd/m² per unit of merged value when the exposures are photographic (see above).
inline constexpr double kPhotographicLuminance = 12.5 / 100;

// Reads a bracket's photos and their exposures: `times` (seconds, in file order) when not
// empty, else each file's EXIF. Throws InputError naming the file and the reason when a
// photo cannot be read, differs in size or bit depth from the first, is all black, has no
// EXIF ExposureTime (and no `times` were given), or when the bracket has fewer than two
// photos, `times` does not hold one positive time per photo, or all shots share one
// exposure (a single exposure: no dynamic range to merge).
Bracket load_bracket(std::string name, std::span<const std::filesystem::path> files,
                     std::span<const double> times);

// Exposure times alone (when the other bracket lacks ISO or f-number: one scale for both).
void use_exposure_times_only(Bracket& bracket);

// Throws InputError naming the first file when all shots share one exposure (within 5 %).
void check_exposure_spread(const Bracket& bracket);

// The index of the shot with the largest and the smallest exposure.
std::size_t longest_shot(const Bracket& bracket);
std::size_t shortest_shot(const Bracket& bracket);

}  // namespace relight
