#include "capture/bracket.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/input_error.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

bool all_black(const Photo& photo) {
  // "Black" allows the sensor's noise floor: nothing above 2 % of full scale.
  const int floor = photo.max_value() / 50;
  return std::none_of(photo.rgb.begin(), photo.rgb.end(),
                      [floor](std::uint16_t v) { return v > floor; });
}

}  // namespace

Bracket load_bracket(std::string name, std::span<const fs::path> files,
                     std::span<const double> times) {
  if (files.size() < 2) {
    fail_input("--" + name, files.empty() ? "no photos"
                                          : files[0].string() +
                                                " is a single exposure: a bracket needs at "
                                                "least two exposures");
  }
  if (!times.empty() && times.size() != files.size()) {
    std::ostringstream reason;
    reason << times.size() << " times for " << files.size() << " photos";
    fail_input("--exposure-times", reason.str());
  }
  Bracket bracket;
  bracket.name = std::move(name);
  std::vector<PhotoExposure> exif;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path& file = files[i];
    Photo photo = read_photo(file);
    if (!bracket.shots.empty()) {
      const Photo& first = bracket.shots.front();
      if (photo.width != first.width || photo.height != first.height) {
        std::ostringstream reason;
        reason << photo.width << " × " << photo.height << " px, but " << files[0].string() << " is "
               << first.width << " × " << first.height;
        fail_input(file.string(), reason.str());
      }
      if (photo.bits != first.bits) {
        fail_input(file.string(), std::to_string(photo.bits) + " bits per channel, but " +
                                      files[0].string() + " has " + std::to_string(first.bits));
      }
    }
    if (all_black(photo)) fail_input(file.string(), "all black");
    PhotoExposure exposure = read_photo_exposure(file);
    if (!times.empty()) {
      if (!(times[i] > 0) || !std::isfinite(times[i])) {
        fail_input("--exposure-times", "time " + std::to_string(i + 1) + " is not positive");
      }
      exposure.exposure_time_s = times[i];
    } else if (!exposure.exposure_time_s) {
      fail_input(file.string(), "no EXIF ExposureTime: give --exposure-times");
    }
    exif.push_back(exposure);
    bracket.files.push_back(file);
    bracket.shots.push_back(std::move(photo));
  }
  bracket.exif = std::move(exif);
  bracket.photographic_exposure =
      std::all_of(bracket.exif.begin(), bracket.exif.end(),
                  [](const PhotoExposure& e) { return e.iso && e.f_number; });
  if (!bracket.photographic_exposure) {
    use_exposure_times_only(bracket);
  } else {
    for (const PhotoExposure& e : bracket.exif) {
      bracket.exposures.push_back(*e.exposure_time_s * (*e.iso / 100) /
                                  (*e.f_number * *e.f_number));
    }
  }
  check_exposure_spread(bracket);
  return bracket;
}

void check_exposure_spread(const Bracket& bracket) {
  const auto [lo, hi] = std::minmax_element(bracket.exposures.begin(), bracket.exposures.end());
  if (*hi < *lo * 1.05) {
    fail_input(bracket.files.front().string(),
               "every photo of the " + bracket.name +
                   " bracket has the same exposure: a bracket needs at least two exposures");
  }
}

void use_exposure_times_only(Bracket& bracket) {
  bracket.photographic_exposure = false;
  bracket.exposures.clear();
  for (const PhotoExposure& e : bracket.exif) bracket.exposures.push_back(*e.exposure_time_s);
}

std::size_t longest_shot(const Bracket& bracket) {
  return static_cast<std::size_t>(
      std::max_element(bracket.exposures.begin(), bracket.exposures.end()) -
      bracket.exposures.begin());
}

std::size_t shortest_shot(const Bracket& bracket) {
  return static_cast<std::size_t>(
      std::min_element(bracket.exposures.begin(), bracket.exposures.end()) -
      bracket.exposures.begin());
}

}  // namespace relight
