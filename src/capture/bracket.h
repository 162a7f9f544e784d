// One auto-exposure bracket (issue 14; the capture of Hao et al. 2020, §IV, paper 003): the
// photos of one fisheye view, taken from one point, and each one's exposure. The exposure of
// a shot is its exposure time, times ISO/ISO₀ · (N₀/N)² when the shots' EXIF ISO or f-number
// differ (relative to the first shot's), since the sensor's signal is proportional to
// t · S / N². Pinned by tests/capture/bracket_test.cpp.
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
  std::vector<double> exposures;  // relative exposure of each shot (s at the first shot's ISO, N)
};

// Reads a bracket's photos and their exposures: `times` (seconds, in file order) when not
// empty, else each file's EXIF. Throws InputError naming the file and the reason when a
// photo cannot be read, differs in size or bit depth from the first, is all black, has no
// EXIF ExposureTime (and no `times` were given), or when the bracket has fewer than two
// photos, `times` does not hold one positive time per photo, or all shots share one
// exposure (a single exposure: no dynamic range to merge).
Bracket load_bracket(std::string name, std::span<const std::filesystem::path> files,
                     std::span<const double> times);

// The index of the shot with the largest and the smallest exposure.
std::size_t longest_shot(const Bracket& bracket);
std::size_t shortest_shot(const Bracket& bracket);

}  // namespace relight
