#include "capture/capture.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "capture/bracket.h"
#include "capture/image_circle.h"
#include "capture/outliers.h"
#include "capture/poisson_fill.h"
#include "capture/view_blend.h"
#include "capture/view_map.h"
#include "common/input_error.h"
#include "math/equirect.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

// The exposure times of each bracket from --exposure-times.
std::pair<std::vector<double>, std::vector<double>> split_times(const CaptureOptions& o) {
  const std::vector<double>& t = o.exposure_times;
  if (t.empty()) return {};
  if (t.size() == o.front.size() + o.back.size()) {
    const auto middle = t.begin() + static_cast<std::ptrdiff_t>(o.front.size());
    return {{t.begin(), middle}, {middle, t.end()}};
  }
  if (t.size() == o.front.size() && t.size() == o.back.size()) return {t, t};
  std::ostringstream reason;
  reason << t.size() << " times for " << o.front.size() << " front and " << o.back.size()
         << " back photos (give one per photo, front first, or one list both brackets share)";
  fail_input("--exposure-times", reason.str());
}

struct View {
  Bracket bracket;
  CapturedView captured;
  HdrPhoto hdr;
  FisheyeView geometry;
};

// The view of a loaded bracket: its image circle (on the longest exposure) and orientation.
View find_view(Bracket bracket, const FisheyeLens& lens, bool front) {
  View v{std::move(bracket), {}, {}, {}};
  const std::size_t longest = longest_shot(v.bracket);
  v.captured.circle =
      find_image_circle(v.bracket.shots[longest], v.bracket.files[longest].string());
  v.geometry = front ? front_view(v.captured.circle, lens) : back_view(v.captured.circle, lens);
  return v;
}

}  // namespace

double map_horizontal_illuminance(const EquirectMap& map) {
  double e = 0;
  for (int j = 0; j < map.height; ++j) {
    const double omega = equirect_row_solid_angle(map.width, map.height, j);
    const double up = equirect_texel_direction(map.width, map.height, 0, j).y;
    if (up <= 0) continue;
    for (int i = 0; i < map.width; ++i) {
      e += luminance(map.texels[static_cast<std::size_t>(j) * map.width + i]) * up * omega;
    }
  }
  return e;
}

CaptureResult capture_environment(const CaptureOptions& options) {
  if (options.width < 16 || options.width % 2 != 0) {
    fail_input("--width", "must be an even number of texels, at least 16");
  }
  if (!(options.lens.fov_rad > kPi) || options.lens.fov_rad >= 2 * kPi) {
    fail_input("--fov-deg",
               "two views cover the sphere only with more than 180° each (and "
               "less than 360°)");
  }
  if (options.illuminance_lux && !(*options.illuminance_lux > 0)) {
    fail_input("--illuminance", "must be positive (lx)");
  }
  const auto [front_times, back_times] = split_times(options);
  Bracket front_bracket = load_bracket("front", options.front, front_times);
  Bracket back_bracket = load_bracket("back", options.back, back_times);
  const Photo& f = front_bracket.shots[0];
  const Photo& b = back_bracket.shots[0];
  if (f.width != b.width || f.height != b.height) {
    std::ostringstream reason;
    reason << b.width << " × " << b.height << " px, but the front photos ("
           << front_bracket.files[0].string() << ") are " << f.width << " × " << f.height;
    fail_input(back_bracket.files[0].string(), reason.str());
  }
  if (f.bits != b.bits) {
    fail_input(back_bracket.files[0].string(), std::to_string(b.bits) +
                                                   " bits per channel, but the front photos have " +
                                                   std::to_string(f.bits));
  }
  if (front_bracket.photographic_exposure != back_bracket.photographic_exposure) {
    use_exposure_times_only(front_bracket);
    use_exposure_times_only(back_bracket);
    check_exposure_spread(front_bracket);
    check_exposure_spread(back_bracket);
  }
  const bool photographic = front_bracket.photographic_exposure;
  View front = find_view(std::move(front_bracket), options.lens, true);
  View back = find_view(std::move(back_bracket), options.lens, false);
  const Bracket* brackets[] = {&front.bracket, &back.bracket};
  const ImageCircle circles[] = {front.captured.circle, back.captured.circle};
  const CameraResponse response = recover_response(brackets, circles);
  front.hdr = merge_bracket(front.bracket, response);
  back.hdr = merge_bracket(back.bracket, response);
  const ViewMap front_map = project_view(front.hdr, front.geometry, options.width);
  const ViewMap back_map = project_view(back.hdr, back.geometry, options.width);
  const double half_fov = options.lens.fov_rad / 2;
  const double front_limit = clean_limit(front_map, back_map, half_fov);
  const double back_limit = clean_limit(back_map, front_map, half_fov);
  front.captured.clean_limit_deg = front_limit * 180 / kPi;
  back.captured.clean_limit_deg = back_limit * 180 / kPi;
  BlendedMap blended = blend_views(front_map, front_limit, back_map, back_limit);
  const std::vector<std::uint8_t> outliers = find_outliers(blended);

  CaptureResult result;
  const int w = blended.width, h = blended.height;
  const std::size_t count = static_cast<std::size_t>(w) * h;
  std::vector<std::uint8_t> fill(count, 0);
  result.mask.assign(count, 0);
  for (int j = 0; j < h; ++j) {
    const double omega = equirect_row_solid_angle(w, h, j);
    for (int i = 0; i < w; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * w + i;
      fill[t] = blended.hole[t] || outliers[t];
      if (outliers[t]) result.removed_sr += omega;
      if (fill[t]) result.filled_sr += omega;
      result.mask[t] = blended.hole[t] ? 1 : outliers[t] ? 2 : blended.clipped[t] ? 3 : 0;
    }
  }
  poisson_fill(w, h, blended.radiance, fill);

  // Calibration.
  EquirectMap map{w, h, std::move(blended.radiance)};
  EquirectMap clipped_part{w, h, std::vector<Rgb>(count)};
  for (std::size_t t = 0; t < count; ++t) {
    if (result.mask[t] == 3) clipped_part.texels[t] = map.texels[t];
  }
  const double e_map = map_horizontal_illuminance(map);
  const double e_clipped = map_horizontal_illuminance(clipped_part);
  if (!(e_map > 0))
    fail_input(options.front[0].string(), "the captured map is black above the horizon");
  result.clipped_share = e_clipped / e_map;
  if (options.illuminance_lux) {
    result.calibrated = true;
    const double reading = *options.illuminance_lux;
    result.scale = reading / e_map;
    if (photographic && e_clipped > 0) {
      const double missing = reading - kPhotographicLuminance * e_map;
      if (missing > 0) {
        result.scale = kPhotographicLuminance;
        const double boost = 1 + missing / (kPhotographicLuminance * e_clipped);
        for (std::size_t t = 0; t < count; ++t) {
          if (result.mask[t] == 3) map.texels[t] *= boost;
        }
      }
    }
  }
  for (Rgb& v : map.texels) v *= result.scale;
  result.horizontal_illuminance = map_horizontal_illuminance(map);
  if (result.clipped_share > 0.001) {
    std::ostringstream warning;
    warning.precision(3);
    warning << "highlights clipped even in the shortest exposure carry at least "
            << 100 * result.clipped_share
            << " % of the horizontal illuminance; their values are lower bounds";
    result.warnings.push_back(warning.str());
  }
  // The merged photos are no longer needed here: moved, not copied (12 MP is 288 MB a view).
  front.captured.merged = {front.hdr.width, front.hdr.height, std::move(front.hdr.radiance)};
  back.captured.merged = {back.hdr.width, back.hdr.height, std::move(back.hdr.radiance)};
  result.front = std::move(front.captured);
  result.back = std::move(back.captured);
  result.response = response;
  result.map = std::move(map);
  return result;
}

}  // namespace relight
