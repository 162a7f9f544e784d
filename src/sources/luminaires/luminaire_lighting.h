// The luminaires' run-time term (Dobashi et al. 1995 Eq. 18, with exact direct light): per
// luminaire j and receiver r
//   E_r = rgb_j · [ D_rj + Σ_k w_jk · T_rjk ]
// with rgb_j = colour · dimmer · on, w_jk the world-frame SH coefficients of the current
// distribution aimed as set (windowed), T the interreflected response to basis Y_k (RGB), and
// D_rj the direct light: exact, I_j(ω_r) · g_r from the current distribution and aim ("exact"
// mode), or Σ_k w_jk · S_rjk from the SH basis direct S ("sh" mode). D is recomputed only when
// a luminaire's aim or distribution changes; a moved curve control point updates the SH
// incrementally (Eq. 21).
//
// The layout: a luminaire the state moves from where the precompute hung it, or adds, is lit at
// run time. Its geometry g_r and directions are traced from every receiver to it (as the
// precompute traces them, sources/luminaires/luminaire_direct.h), so its direct light is exact at
// once; its interreflection is the stored gather operator's bounce of that direct light
// (engine/runtime_scene.h), per unit colour so that a dimmer or colour needs no bounce again.
// Until update() bounces it (a first frame), the stored response T of the nearest precomputed
// luminaire, weighted by this one's SH coefficients, stands in for its interreflection.
// Pinned by tests/cli/layout_test.cpp.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/glossy_first_bounce.h"
#include "engine/light_term.h"
#include "engine/runtime_scene.h"
#include "light/distribution.h"
#include "light/luminaire_state.h"
#include "math/sh_window.h"
#include "scene/scene.h"
#include "sources/luminaires/luminaire_direct.h"
#include "sources/luminaires/luminaire_sh_curve.h"
#include "sources/luminaires/luminaire_transfer_view.h"

namespace relight {

struct LuminaireTransferSet {
  std::span<const LuminaireTransferView> luminaires;  // scene order
  std::size_t receivers = 0;
  int sh_order = 8;
  bool direct_sh_mode = false;
};

class LuminaireLighting : public LightTerm {
 public:
  // Lit as the scene sets every luminaire.
  LuminaireLighting(LuminaireTransferSet transfer, const Scene& scene, ShWindow window);

  std::string_view kind() const override { return "luminaires"; }
  // Applies the luminaires' states (the scene's in scene order, then those the state adds);
  // loads IES/LDT files of changed distributions and traces the direct geometry of moved and
  // added luminaires. Returns whether the term's sum changed. A state that moves or adds one
  // needs set_runtime() with a run-time scene that bounces (std::logic_error otherwise).
  bool set_state(std::span<const LuminaireState> states);
  bool set_state(const LightingState& state) override { return set_state(state.luminaires); }
  // Whether a state moves a precomputed luminaire or adds one (it then needs set_runtime()).
  bool needs_runtime(std::span<const LuminaireState> states) const;
  // The receivers, occluders and gather operator moved and added luminaires are traced
  // against and bounced through; must outlive the term.
  void set_runtime(const RuntimeScene* runtime) { runtime_ = runtime; }
  // Whether update() bounces moved and added luminaires' light (the converged frame; the
  // default) or leaves the nearest stored response in its place (a first frame).
  void set_bounce_live(bool bounce) { bounce_live_ = bounce; }
  // Bounces the light of moved and added luminaires whose bounce is out of date (with
  // set_bounce_live(true)).
  bool update() override;
  // Whether every lit luminaire's interreflection is its own (stored, or bounced at run time).
  bool converged() const;
  // Luminaires lit at run time (moved or added), and the wall time of the last traces and
  // bounces, seconds.
  std::size_t live_count() const;
  double last_trace_seconds() const { return trace_seconds_; }
  double last_bounce_seconds() const { return bounce_seconds_; }

  void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const override;

  // The glossy surfaces' first reflection of each luminaire's direct light
  // (engine/glossy_first_bounce.h), Γ per luminaire, recomputed when its aim or distribution
  // changes; its image in near-mirror planes traced once per `glossy`. Null (or "sh" direct
  // mode, which has no light direction per receiver): none.
  // `glossy` must outlive the term.
  void set_glossy(const GlossyFirstBounce* glossy) override;
  // out (3 per receiver) += Σ_j rgb_j · Γ_j.
  void add_glossy(std::span<float> out) const override;
  std::size_t transfer_bytes() const override;
  // Each luminaire through its luminous opening (sources/luminaires/luminaire_direct.h).
  std::unique_ptr<const DirectLights> direct_lights(const Occluders& occluders,
                                                    int opening_samples) const override;

  // The luminaires as the current state sets them, for exact direct light at any point
  // (sources/luminaires/luminaire_direct.h).
  std::vector<LuminaireLight> lights(int opening_samples = 16) const;
  // The current photometry of luminaire j (as loaded for its state).
  const Distribution& distribution(std::size_t j) const { return luminaires_.at(j).distribution; }
  // The luminaires as the state sets them (the scene's, then those it adds).
  std::span<const LuminaireState> states() const { return states_; }
  // How many distribution changes were one moved curve control point, updated incrementally.
  std::size_t incremental_curve_updates() const { return incremental_curve_updates_; }

 private:
  struct Lit {  // one luminaire as the current state lights it
    Distribution distribution;
    std::vector<double> sh;                // world-frame SH coefficients of I (windowed)
    std::optional<CurveProjector> curve;   // kept for curve distributions (Eq. 19-21)
    std::vector<float> direct;             // D_r without colour (exact mode)
    std::vector<float> glossy;             // Γ_r, 3 per receiver (with glossy surfaces)
    std::vector<MirrorPath> mirror_paths;  // through near-mirrors, traced for glossy_
    bool mirror_traced = false;
    std::vector<float> weights;  // K × 3: rgb_c · w_k (indirect, and "sh" direct)
    float rgb[3] = {0, 0, 0};
    bool active = false;
    // Lit at run time (moved or added): its traced geometry, and its bounced light per unit
    // colour (3 per receiver), of the current geometry and distribution when `bounced`.
    bool live = false;
    DirectGeometry geometry;
    std::vector<float> indirect;
    bool bounced = false;
    // The stored transfer whose interreflection this one uses (its own when not live; the
    // nearest stored luminaire's until bounced); none in a scene without stored luminaires.
    std::optional<std::size_t> stored;
  };
  // The direct geometry of luminaire j: stored, or traced at run time.
  struct Geometry {
    std::span<const float> dir_x, dir_y, dir_z, factor;
  };
  Geometry geometry(std::size_t j) const;
  bool is_moved(std::size_t j, const LuminaireState& s) const;
  void trace_live(std::size_t j, const LuminaireState& s);

  // Luminaire j's exact direct light (when `direct_changed`; its distribution already projected
  // for s) and its weights.
  void apply(std::size_t j, const LuminaireState& s, bool direct_changed);
  void project_distribution(std::size_t j, const LuminaireState& s);
  void respond_glossy(std::size_t j, const LuminaireState& s);

  LuminaireTransferSet transfer_;
  ShWindow window_;
  std::vector<LuminaireState> states_;
  std::vector<Luminaire> specs_;  // the scene's, as precomputed
  std::vector<Lit> luminaires_;
  std::size_t incremental_curve_updates_ = 0;
  const GlossyFirstBounce* glossy_ = nullptr;
  const RuntimeScene* runtime_ = nullptr;
  bool bounce_live_ = true;
  std::vector<float> scratch_;  // 3 per receiver: a live luminaire's direct light to bounce
  double trace_seconds_ = 0, bounce_seconds_ = 0;
};

}  // namespace relight
