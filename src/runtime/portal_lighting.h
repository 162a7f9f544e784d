// The run-time side of one portal (the interior-scene paper §5, issue 4 item 4): from the
// portal's lighting state (environment, window tint, frost, where the exterior objects are)
// to the two things the weighted sum needs — the shell's radiance cubemap in pulse and Haar
// form for the direct component (a sparse dot product per receiver, the paper's Appendix
// Eq. 7), and the shell's SH coefficients times colour as weights of the stored indirect
// responses. Rebuilt only when the portal's state changes.
#pragma once

#include <functional>
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

struct PortalLighting {
  Shell shell;
  ShellWorkspace workspace;
  ShellCubemap cubemap;        // the shell's cells and their per-face Haar transform
  std::vector<float> weights;  // K × 3: the shell's SH coefficients (indirect weights)
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
