// What a window's glass shows looking out. In the studio's vertex frames (docs/studio-protocol.md,
// "Frame RLFR"): the mean radiance of the view out of it, i.e. of its shell (Yue et al. 2009 §4:
// the environment as seen from the portal) over the outward hemisphere, weighted by texel solid
// angle; the sun's own deposit is left out: a 0.5° disc averaged over a hemisphere would wash the
// whole pane out. Per direction, for a client that draws the outside through the glass per pixel
// ("Window views RLWV"): the shell itself, and behind clear glass the sun disc, which is traced
// apart from the shell (sources/portals/portal_lighting.h) and so drawn apart from it.
// Pinned by tests/runtime/window_view_test.cpp and studio.window_view.
#pragma once

#include <optional>
#include <span>

#include "light/sky_model.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "sources/portals/portal_sun.h"
#include "sources/portals/shell.h"

namespace relight {

Rgb window_view_radiance(const Shell& shell, Vec3 outward);

// The view out of one window, per direction.
struct WindowView {
  const Shell* shell = nullptr;  // the exterior seen from the portal's centre, tint and frost in
  Vec3 centre;                   // the portal's centre
  std::optional<SunDisc> sun;    // the sun traced apart from the shell, when it is
  Rgb sun_luminance;             // over its disc, cd/m², the glass's tint included
};

// Portal `portal`'s view: its shell, and the traced sun of `suns` that shines through it.
WindowView window_view(const Shell& shell, Vec3 centre, std::uint32_t portal,
                       std::span<const PortalSun> suns);

}  // namespace relight
