// What a window's glass shows in the studio's vertex frames (docs/studio-protocol.md, "Frame
// RLFR"): the mean radiance of the view out of it, i.e. of its shell (Yue et al.
// 2009 §4: the environment as seen from the portal) over the outward hemisphere, weighted by
// texel solid angle. The sun's own deposit is left out: through glass one sees the sky, and a
// 0.5° disc averaged over a hemisphere would wash the whole pane out.
#pragma once

#include "math/rgb.h"
#include "math/vec3.h"
#include "sources/portals/shell.h"

namespace relight {

Rgb window_view_radiance(const Shell& shell, Vec3 outward);

}  // namespace relight
