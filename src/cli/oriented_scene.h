// The scene as the light sees it: its static triangles that face out of the closed space they
// bound turned (trace/surface_orientation.h), with a warning on stderr that says how many.
// `relight precompute` and `relight reference` both load scenes through it, so the transfer and
// its reference light the same surfaces.
#pragma once

#include "scene/scene.h"

namespace relight {

// `report`: print the warning (false on every rank of a precompute but the first).
Scene oriented_scene(Scene scene, bool report = true);

}  // namespace relight
