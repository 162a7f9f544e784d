#include "cli/view_args.h"

#include <cstdio>

#include <CLI/CLI.hpp>

#include "common/input_error.h"
#include "scene/camera.h"

namespace relight {

void add_view_options(CLI::App& cmd, ViewArgs& args) {
  cmd.add_option("--camera", args.camera, "scene camera to render (default: the first)");
  cmd.add_option("--width", args.width, "image width in pixels")->check(CLI::Range(1, 16384));
  cmd.add_option("--height", args.height, "image height in pixels")->check(CLI::Range(1, 16384));
  cmd.add_option("-o,--output", args.output, "image to write (.png or .exr)");
  cmd.add_option("--exposure", args.exposure, "exposure EV100 for PNG (default: automatic)")
      ->each([&args](const std::string&) { args.exposure_given = true; });
  cmd.add_option("--false-color", args.false_color, "false colour view: lux or luminance")
      ->check(CLI::IsMember({"lux", "luminance"}));
  cmd.add_option("--range", args.range, "false colour range MIN:MAX in lx or cd/m2");
}

DisplayOptions display_options(const ViewArgs& args) {
  DisplayOptions d;
  if (args.exposure_given) d.exposure_ev = args.exposure;
  if (args.false_color.empty()) {
    if (!args.range.empty()) fail_input("--range", "needs --false-color lux|luminance");
    return d;
  }
  FalseColor f;
  f.quantity = args.false_color == "lux" ? Quantity::kIlluminance : Quantity::kLuminance;
  if (!args.range.empty()) {
    const RangeArgument r = parse_range(args.range);
    f.min = r.min;
    f.max = r.max;
  }
  d.false_color = f;
  return d;
}

Camera choose_camera(const Scene& scene, const std::optional<std::string>& name,
                     const Bounds& bounds) {
  if (name) {
    const Camera* c = scene.find_camera(*name);
    if (!c) fail_input("--camera", "scene has no camera named \"" + *name + "\"");
    return *c;
  }
  return scene.cameras.empty() ? default_camera(bounds) : scene.cameras.front();
}

void warn_back_sides(const Camera& camera, std::size_t back_side_pixels, std::size_t pixels) {
  if (pixels == 0 || 2 * back_side_pixels <= pixels) return;
  std::fprintf(stderr,
               "warning: camera \"%s\": %.0f%% of the pixels see only the back of surfaces "
               "(black): is the eye inside an object, or outside the room? (eye %g, %g, %g)\n",
               camera.name.c_str(), 100.0 * static_cast<double>(back_side_pixels) / pixels,
               camera.eye.x, camera.eye.y, camera.eye.z);
}

}  // namespace relight
