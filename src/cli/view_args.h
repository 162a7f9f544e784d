// Options shared by the commands that write images (reference, render): the camera
// and size, the output file and how a PNG displays physical values.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "render/image_io.h"
#include "scene/scene.h"

namespace CLI {
class App;
}

namespace relight {

struct ViewArgs {
  std::string camera, output, false_color, range;
  int width = 640, height = 480;
  double exposure = 0;
  bool exposure_given = false;
};

// Registers --camera, --width, --height, -o, --exposure, --false-color, --range.
void add_view_options(CLI::App& cmd, ViewArgs& args);
// The display options the arguments ask for (validating --range).
DisplayOptions display_options(const ViewArgs& args);
// The named camera (InputError naming --camera if absent), else the scene's first,
// else one looking into `bounds`.
Camera choose_camera(const Scene& scene, const std::optional<std::string>& name,
                     const Bounds& bounds);
// Warns on stderr when most of an image's pixels see only the back of surfaces (black): the
// eye is inside an object, or outside the room behind a wall.
void warn_back_sides(const Camera& camera, std::size_t back_side_pixels, std::size_t pixels);

}  // namespace relight
