// The paths along which `relight bench` moves an edit frame after frame: what a designer
// dragging a control does, in small steps.
#pragma once

#include <cstddef>

#include "scene/environment_spec.h"
#include "sources/transfer_file.h"

namespace relight {

// The opaque material on the most vertices (what a designer repaints: a wall, the floor).
std::size_t most_used_material(const TransferFile& t);

// The next frame's sky: a small change of the kind a designer scrubbing time makes (a sun by
// place and time a minute later, by angles a quarter degree further, a map turned a degree, a
// brightness 1% up or down).
void advance_sky(EnvironmentSpec& e, int frame);

}  // namespace relight
