// The run-time side of one portal (Yue et al. 2009 §5, issue 4 item 4): from the
// portal's lighting state (environment, window tint, frost, where the exterior objects are)
// to the two things the weighted sum needs — the shell's radiance cubemap in pulse and Haar
// form for the direct component (a sparse dot product per receiver, the paper's Appendix
// Eq. 7), and the shell's SH coefficients times colour as weights of the stored indirect
// responses. Rebuilt only when the portal's state changes.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "engine/source_term.h"
#include "light/environment.h"
#include "scene/scene.h"
#include "sources/portal/cubemap_encoding.h"
#include "sources/portal/portal_state.h"
#include "sources/portal/portal_transfer_view.h"
#include "sources/portal/shell.h"

namespace relight {

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
                            int sh_order, const PortalState& state, const Scene& scene);

struct PortalTransferSet {
  std::span<const PortalTransferView> portals;  // scene order
  std::size_t receivers = 0;
  int sh_order = 6;
};

// The portals' run-time term (Yue et al. 2009 §5, Appendix Eq. 7): per portal the sparse dot
// product of each receiver's direct cubemap record with the shell's cubemap, plus the
// shell's SH weights on the stored indirect responses. A portal's shell is rebuilt only when
// its state changes.
class PortalSetLighting : public SourceTerm {
 public:
  // Lit as the scene sets every portal.
  PortalSetLighting(PortalTransferSet transfer, const Scene& scene);

  // Applies the portals' states (scene order). Returns whether the term's sum changed.
  bool set_state(std::span<const PortalState> states);

  void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const override;
  std::size_t transfer_bytes() const override;

  const PortalLighting& portal(std::size_t p) const { return portals_.at(p); }

 private:
  PortalTransferSet transfer_;
  const Scene* scene_;
  std::vector<PortalState> states_;
  std::vector<PortalLighting> portals_;
};

}  // namespace relight
