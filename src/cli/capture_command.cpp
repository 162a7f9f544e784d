// `relight capture --front F1 F2 ... --back B1 B2 ... -o ROOM.exr [--fov-deg 190]
// [--lens equidistant|equisolid|stereographic] [--width 1024] [--exposure-times T1,T2,...]
// [--illuminance LUX] [--debug DIR]`: two fisheye brackets → a float RGB OpenEXR (ZIP)
// environment map, cd/m² with --illuminance (capture/capture.h, docs/capture.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "capture/capture.h"
#include "cli/commands.h"
#include "common/input_error.h"
#include "image/image_exr.h"
#include "image/image_png.h"
#include "render/tone_map.h"

namespace relight {

namespace {

namespace fs = std::filesystem;

struct CaptureArgs {
  std::vector<std::string> front, back;
  std::string output, lens = "equidistant", times, debug;
  double fov_deg = 190;
  int width = 1024;
  std::optional<double> illuminance;
};

// "0.004,1/60,0.25": seconds, each a decimal or a fraction.
std::vector<double> parse_times(const std::string& text) {
  std::vector<double> times;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto fail = [&] {
      fail_input("--exposure-times", "\"" + item + "\" is not a time in seconds");
    };
    const std::size_t slash = item.find('/');
    char* end = nullptr;
    double value = std::strtod(item.c_str(), &end);
    if (end == item.c_str()) fail();
    if (slash != std::string::npos) {
      if (end != item.c_str() + slash) fail();
      const char* denominator = item.c_str() + slash + 1;
      const double d = std::strtod(denominator, &end);
      if (end == denominator || !(d > 0)) fail();
      value /= d;
    }
    while (*end == ' ') ++end;
    if (*end != '\0' || !(value > 0) || !std::isfinite(value)) fail();
    times.push_back(value);
  }
  if (times.empty()) fail_input("--exposure-times", "no times");
  return times;
}

FisheyeProjection parse_lens(const std::string& name) {
  if (name == "equidistant") return FisheyeProjection::kEquidistant;
  if (name == "equisolid") return FisheyeProjection::kEquisolid;
  if (name == "stereographic") return FisheyeProjection::kStereographic;
  fail_input("--lens", "\"" + name + "\" is not equidistant, equisolid or stereographic");
}

// ln X(z) of each channel against z, in the channel's colour, on a dark grid.
Image8 response_plot(const CameraResponse& response) {
  constexpr int kW = 512, kH = 320;
  Image8 plot = make_image8(kW, kH, {24, 24, 24});
  for (int k = 1; k < 8; ++k) {
    for (int y = 0; y < kH; ++y) plot.set(k * kW / 8, y, {60, 60, 60});
    for (int x = 0; x < kW; ++x) plot.set(x, k * kH / 8, {60, 60, 60});
  }
  double lo = 1e30, hi = -1e30;
  for (const auto& channel : response.exposure) {
    for (const double x : channel) {
      if (x <= 0) continue;
      lo = std::min(lo, std::log(x));
      hi = std::max(hi, std::log(x));
    }
  }
  if (!(hi > lo)) return plot;
  const Rgb8 colours[3] = {{255, 80, 80}, {80, 255, 80}, {100, 140, 255}};
  for (int c = 0; c < 3; ++c) {
    const auto& channel = response.exposure[static_cast<std::size_t>(c)];
    for (int x = 0; x < kW; ++x) {
      const double v = channel[static_cast<std::size_t>(x) * channel.size() / kW];
      if (v <= 0) continue;
      const int y = static_cast<int>((1 - (std::log(v) - lo) / (hi - lo)) * (kH - 1));
      for (int dy = -1; dy <= 1; ++dy) {
        if (y + dy >= 0 && y + dy < kH) plot.set(x, y + dy, colours[c]);
      }
    }
  }
  return plot;
}

Image8 mask_image(const CaptureResult& result) {
  const Rgb8 colours[4] = {{0, 0, 0}, {220, 40, 40}, {40, 90, 230}, {240, 220, 40}};
  Image8 image = make_image8(result.map.width, result.map.height);
  for (int j = 0; j < result.map.height; ++j) {
    for (int i = 0; i < result.map.width; ++i) {
      image.set(i, j, colours[result.mask[static_cast<std::size_t>(j) * result.map.width + i]]);
    }
  }
  return image;
}

void write_debug(const fs::path& folder, const CaptureResult& result) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) fail_input(folder.string(), "cannot create the folder: " + error.message());
  const auto write = [&](const std::string& name, const Image8& image) {
    write_png(folder / name, image);
  };
  write("front_merged.png", tone_map(result.front.merged, std::nullopt).image);
  write("back_merged.png", tone_map(result.back.merged, std::nullopt).image);
  write("response.png", response_plot(result.response));
  write("mask.png", mask_image(result));
  write(
      "map.png",
      tone_map(Image{result.map.width, result.map.height, result.map.texels}, std::nullopt).image);
}

int run_capture(const CaptureArgs& args) {
  CaptureOptions options;
  for (const std::string& f : args.front) options.front.emplace_back(f);
  for (const std::string& b : args.back) options.back.emplace_back(b);
  if (!args.times.empty()) options.exposure_times = parse_times(args.times);
  options.lens = {parse_lens(args.lens), args.fov_deg * kPi / 180};
  options.width = args.width;
  options.illuminance_lux = args.illuminance;
  const CaptureResult result = capture_environment(options);
  write_exr(args.output, Image{result.map.width, result.map.height, result.map.texels},
            ExrChannels::kFloat);
  for (const auto& [name, view] : {std::pair{"front", &result.front}, {"back", &result.back}}) {
    std::printf("%s: image circle centre (%.1f, %.1f) px, radius %.1f px; used to %.1f° off axis\n",
                name, view->circle.cx, view->circle.cy, view->circle.radius, view->clean_limit_deg);
  }
  std::printf("removed %.3f sr as outliers, filled %.3f sr\n", result.removed_sr, result.filled_sr);
  if (result.calibrated) {
    std::printf("calibrated: horizontal illuminance %.1f lx, values in cd/m²\n",
                result.horizontal_illuminance);
  } else {
    std::printf("not calibrated (no --illuminance): values are relative radiance, not cd/m²\n");
  }
  for (const std::string& warning : result.warnings) {
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
  if (!args.debug.empty()) write_debug(args.debug, result);
  std::printf("wrote %s (%d × %d)\n", args.output.c_str(), result.map.width, result.map.height);
  return 0;
}

}  // namespace

void add_capture_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<CaptureArgs>();
  CLI::App* cmd = app.add_subcommand(
      "capture", "Two fisheye exposure brackets (front looks north, back south) → an HDR map");
  cmd->add_option("--front", args->front, "photos of the front bracket (JPEG, PNG, TIFF)")
      ->required();
  cmd->add_option("--back", args->back, "photos of the back bracket")->required();
  cmd->add_option("-o,--output", args->output, "environment map to write (.exr)")->required();
  cmd->add_option("--fov-deg", args->fov_deg, "lens field of view across the circle (degrees)")
      ->capture_default_str();
  cmd->add_option("--lens", args->lens, "equidistant, equisolid or stereographic")
      ->capture_default_str();
  cmd->add_option("--width", args->width, "map width in texels (height = width / 2)")
      ->capture_default_str();
  cmd->add_option("--exposure-times", args->times,
                  "seconds, comma-separated, in file order (front, then back; or one list for "
                  "both); default: EXIF");
  cmd->add_option("--illuminance", args->illuminance,
                  "lux-meter reading at the camera facing up: values become cd/m²");
  cmd->add_option("--debug", args->debug, "folder for merged views, masks, response curves (PNG)");
  cmd->callback([args, &action] { action = [args] { return run_capture(*args); }; });
}

}  // namespace relight
