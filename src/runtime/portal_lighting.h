// The run-time side of one portal (the interior-scene paper §5, issue 4 item 4): from the
// portal's lighting state (environment, window tint, frost, where the exterior objects are)
// to the two things the weighted sum needs — the shell's radiance cubemap in pulse and Haar
// form for the direct component (a sparse dot product per receiver, the paper's Appendix
// Eq. 7), and the shell's SH coefficients times colour as weights of the stored indirect
// responses. Rebuilt only when the portal's state changes.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "light/environment.h"
#include "runtime/lighting_state.h"
#include "runtime/shell.h"
#include "scene/scene.h"
#include "transfer/cubemap_encoding.h"

namespace relight {

struct PortalTransferView;

// Turns an environment spec into an Environment; map environments need their image read
// (render/environment_map_io.h), which the caller supplies. The default handles uniform and
// sky environments and refuses maps with an InputError.
using EnvironmentLoader = std::function<Environment(const EnvironmentSpec&)>;
Environment environment_without_images(const EnvironmentSpec& spec);

// A sun seen through clear glass: what a renderer can trace per pixel instead of taking it
// from the shell's cubemap cell (2.8° at 32² a face) interpolated between vertices.
struct PortalSun {
  Vec3 direction;   // unit, toward the sun
  Rgb illuminance;  // lx on a plane facing the sun, tint included
};

struct PortalLighting {
  Shell shell;
  ShellWorkspace workspace;
  ShellCubemap cubemap;  // the shell's cells and their per-face Haar transform
  // The same without a sharp sun's cell deposit, valid when sharp_sun is set: direct light
  // for renderers that add the sun per pixel.
  ShellCubemap sky_cubemap;
  std::vector<Rgb> sky_cells;  // scratch: its cells
  // Set when the shell holds an unoccluded sun behind clear (unfrosted) glass; frosted
  // glass spreads the sun over the shell and it stays in the cubemap.
  std::optional<PortalSun> sharp_sun;
  std::vector<float> weights;  // K × 3: SH of the shell's outward half (indirect weights)
  bool active = false;         // any light at all
  double seconds = 0;          // wall time of the last update
};

// The exterior objects of the scene placed as `placements` says (scene order; hidden ones
// left out), one shell object per object and material.
std::vector<ExteriorObject> placed_exterior(const Scene& scene,
                                            const std::vector<ExteriorPlacement>& placements);

void update_portal_lighting(PortalLighting& lighting, const PortalTransferView& portal,
                            int sh_order, const PortalState& state, const Scene& scene,
                            const EnvironmentLoader& load);

}  // namespace relight
