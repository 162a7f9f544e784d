// The run-time side of one portal (Yue et al. 2009 §5): from the portal's lighting state
// (environment, window tint, frost, where the exterior objects are) to the two things the weighted
// sum needs — the shell's radiance cubemap in pulse (as texels and as planes for the runs) and Haar
// form for the direct component (a sparse dot product per receiver, the paper's Appendix Eq. 7),
// and the shell's SH coefficients times colour as weights of the stored indirect responses. Rebuilt
// only when the portal's state changes.
//
// Behind clear glass the sun is not in the shell: it is traced exactly at every receiver
// (sources/portals/portal_sun.h), and its interreflection is that exact direct light bounced at run
// time through the stored gather operator (engine/runtime_scene.h) — a sharp patch and the light it
// throws, which the shell's 2.8° cell and l < 6 SH would smear. Behind frosted glass the sun stays
// in the shell, which spreads it (shell_frost.h).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/glossy_first_bounce.h"
#include "engine/light_term.h"
#include "engine/runtime_scene.h"
#include "light/environment.h"
#include "light/portal_state.h"
#include "scene/scene.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/portal_sun.h"
#include "sources/portals/portal_transfer_view.h"
#include "sources/portals/shell.h"

namespace relight {

struct PortalLighting {
  Shell shell;
  ShellWorkspace workspace;
  ShellCubemap cubemap;  // the shell's cells and their per-face Haar transform
  // Set when the sun is traced exactly (a sun in front of clear glass; the shell then holds
  // no sun disc); frosted glass spreads the sun over the shell and it stays there.
  std::optional<PortalSun> sun;
  std::vector<float> weights;  // K × 3: SH of the shell's outward half (indirect weights)
  bool active = false;         // any light at all
  double seconds = 0;          // wall time of the last update
};

// The exterior objects of the scene placed as `placements` says (scene order; hidden ones
// left out), one shell object per object and material.
std::vector<ExteriorObject> placed_exterior(const Scene& scene,
                                            const std::vector<ExteriorPlacement>& placements);

// Renders portal `index`'s shell for `state` (without the sun disc when the sun is traced
// exactly) and sets its weights and exact sun.
void update_portal_lighting(PortalLighting& lighting, std::uint32_t index,
                            const PortalTransferView& portal, int sh_order,
                            const PortalState& state, const Scene& scene);

struct PortalTransferSet {
  std::span<const PortalTransferView> portals;  // scene order
  std::size_t receivers = 0;
  int sh_order = 6;
};

// The portals' run-time term (Yue et al. 2009 §5, Appendix Eq. 7): per portal the sparse dot
// product of each receiver's direct cubemap record with the shell's cubemap, plus the
// shell's SH weights on the stored indirect responses; plus the exactly traced suns at every
// receiver and their light bounced through the scene. A portal's shell is rebuilt only when
// its state changes, the suns only when one of them changes.
// How the suns' light is bounced when they change.
enum class SunBounce {
  // From the last solution, to the looser kWarmBounceTolerance: a sun moved a minute takes a
  // bounce or two (the studio's time of day).
  kWarm,
  // From nothing, to the scene's tolerance, as in a fresh process.
  kCold,
  // At the sensor rows alone, through the sensors' importance (the runtime scene must have
  // solved it): the suns' direct light and its bounce are 0 at the vertices. For a caller that
  // reads only the sensors under thousands of suns (`relight annual`).
  kSensors,
};

class PortalSetLighting : public LightTerm {
 public:
  // Lit as the scene sets every portal. `runtime` traces the suns and bounces their light
  // (without a stored gather operator the suns' interreflection is left out); it may be null
  // only for a scene without portals.
  PortalSetLighting(PortalTransferSet transfer, const RuntimeScene* runtime, const Scene& scene,
                    SunBounce sun_bounce = SunBounce::kWarm);
  // Changes how the suns bounce, and lights them again that way.
  void set_sun_bounce(SunBounce sun_bounce);

  std::string_view kind() const override { return "portals"; }
  // Applies the portals' states (scene order). Returns whether the term's sum changed.
  bool set_state(std::span<const PortalState> states);
  bool set_state(const LightingState& state) override { return set_state(state.portals); }

  void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const override;
  std::size_t transfer_bytes() const override;

  std::size_t size() const { return portals_.size(); }
  const PortalLighting& portal(std::size_t p) const { return portals_.at(p); }
  // The suns traced exactly now, and what they are traced against (only for a scene with
  // portals): for per-pixel tracing.
  std::span<const PortalSun> suns() const { return suns_; }
  SunGeometry sun_geometry() const;
  // Their direct irradiance (penumbra included, the room's shadows, no movable object's), 3 per
  // receiver (RGB), as the last update traced it: at the sensor rows alone when the sun bounce
  // is SunBounce::kSensors (the vertex rows zero); empty when there is no sun.
  std::span<const float> sun_direct() const { return sun_direct_; }
  // Wall time of the last suns' update: the direct light at every receiver and its bounce.
  double sun_seconds() const { return sun_seconds_; }
  double sun_bounce_seconds() const { return sun_bounce_seconds_; }
  // The glossy surfaces' first reflection of the suns (engine/glossy_first_bounce.h), made
  // again with every sun update; null: none. `glossy` must outlive the term.
  void set_glossy(const GlossyFirstBounce* glossy) override;
  // out (3 per receiver) += the suns' Γ.
  void add_glossy(std::span<float> out) const override;
  // The suns traced exactly, each through its window's glass (sources/portals/portal_sun.h);
  // the skylight through the shells is not a direct light at a point: it is in add_block's
  // sum with or without direct light.
  std::unique_ptr<const DirectLights> direct_lights(const Occluders& occluders,
                                                    int opening_samples) const override;

 private:
  void update_suns();
  void respond_glossy(const SunGeometry& geometry, std::span<const float> reflected);

  PortalTransferSet transfer_;
  const RuntimeScene* runtime_;
  const Scene* scene_;
  std::vector<PortalState> states_;
  std::vector<PortalLighting> portals_;
  std::vector<GlassBounds> bounds_;  // per portal: around its glass
  std::vector<PortalSun> suns_;      // the portals' exact suns
  // What suns_ was traced for: per sun its portal, disc, illuminance and exterior placement.
  struct SunKey {
    std::uint32_t portal;
    Vec3 direction;
    Rgb illuminance;
    std::vector<ExteriorPlacement> exterior;
    bool operator==(const SunKey&) const = default;
  };
  std::vector<SunKey> sun_keys_;
  SunBounce sun_bounce_ = SunBounce::kWarm;
  std::vector<float> sun_direct_, sun_indirect_;  // 3 per receiver (empty: no sun)
  std::vector<float> sun_glossy_;                 // Γ of the suns, 3 per receiver (empty: none)
  const GlossyFirstBounce* glossy_ = nullptr;
  double sun_seconds_ = 0, sun_bounce_seconds_ = 0;
};

}  // namespace relight
