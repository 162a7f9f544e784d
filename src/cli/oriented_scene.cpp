#include "cli/oriented_scene.h"

#include <cstdio>
#include <string>

#include "trace/surface_orientation.h"

namespace relight {

Scene oriented_scene(Scene scene, bool report) {
  const SurfaceOrientation orientation = orient_scene_surfaces(scene);
  const std::string warning = orientation_warning(orientation);
  if (report && !warning.empty())
    std::fprintf(stderr, "warning: %s: %s\n", scene.file.string().c_str(), warning.c_str());
  return scene;
}

}  // namespace relight
