// The run-time half of precomputed transfer: lighting state → small weight vectors → one weighted
// sum over the stored transfer → irradiance per receiver. The Relighter is the list of the kinds
// of light (sources/light_terms.h), each known only through the contract of engine/light_term.h
// (its part of the state, its sum over a block, its glossy first reflection), plus the
// corrections above them: the live material edit (engine/albedo_edit.h), the glossy surfaces'
// first bounce (engine/glossy_first_bounce.h) and the movable objects
// (sources/objects/object_lighting.h). It keeps a partial sum per kind and sums a kind again only
// after its state changed; relight() allocates nothing and uses every core.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/albedo_edit.h"
#include "light/distribution.h"
#include "math/sh_window.h"
#include "runtime/lighting_state.h"
#include "scene/scene.h"
#include "sources/light_terms.h"
#include "sources/objects/object_lighting.h"
#include "sources/transfer_view.h"

namespace relight {

struct RelighterSettings {
  ShWindow window = ShWindow::kSigma;  // applied to the SH weights of every luminaire
  EmitterLightingSettings emitters;    // sampling of near-field emitters
  // A moved sun's bounce starts from the last one (PortalSetLighting): false for a sequence
  // of unrelated skies whose every frame must equal a fresh process's (`relight annual`).
  bool warm_sun_bounce = true;
  // Only the sensors are read (`relight annual`): relight() sums the blocks that hold sensor
  // rows (the other vertex rows are left as they were) and the suns reach the sensors through
  // their importance (engine/sensor_importance.h), solved once when the Relighter is made —
  // seconds — instead of a pass over the gather operator per bounce for every sun. Ignored
  // (every row computed, the suns bounced from nothing) in a scene with movable objects or
  // glossy materials, whose light at the sensors depends on the whole room's, and from the
  // first state that edits materials on.
  bool sensors_only = false;
  // The top-level environment's interreflection added (sources/environment/environment_lighting.h);
  // false: its direct light alone, and the movable objects' change to it alone, nothing
  // bounced (`--max-bounces 1`).
  bool environment_bounce = true;
  // The sensors' importance already solved for this transfer (another Relighter's: see
  // sensor_importance()), taken instead of solving it again.
  std::shared_ptr<const SensorImportance> sensor_importance;
};

class Relighter {
 public:
  Relighter(TransferView transfer, const Scene& scene, const RelighterSettings& settings = {});
  Relighter(const Relighter&) = delete;  // the terms refer to transfer_
  Relighter& operator=(const Relighter&) = delete;

  // Updates weights (and direct fields of luminaires whose aim or distribution
  // changed). Loads IES/LDT files of changed distributions.
  void set_state(const LightingState& state);
  const LightingState& state() const { return state_; }

  // Irradiance per receiver, RGB interleaved: out.size() == 3 · receivers. With the
  // state's material edits (engine/albedo_edit.h), the interreflected light of the edited
  // room: converged, or after set_material_bounces(n ≥ 0), n bounces of the edit's light (a
  // first, approximate frame; material_edit_final() says which the last relight() gave). Without
  // direct light, what renderers that evaluate direct light per pixel still need: every kind's
  // sum without what its direct_lights() gives at a point (engine/light_term.h), which such a
  // renderer traces itself (runtime/direct_light.h).
  // Each kind keeps its partial sum between calls, and only the kinds whose state changed since
  // are summed again.
  void relight(std::span<float> out, bool include_direct = true);
  // The suns traced exactly (behind clear glass) and what they are traced against, for
  // per-pixel tracing (sources/portals/portal_sun.h).
  std::span<const PortalSun> suns() const { return lights_.portals().suns(); }
  SunGeometry sun_geometry() const { return lights_.portals().sun_geometry(); }
  const PortalSetLighting& portals() const { return lights_.portals(); }
  // Every kind of light of the scene, in the order their sums are added (engine/light_term.h).
  std::span<LightTerm* const> lights() const { return lights_.all(); }
  // The light a material edit bounces: −1 converged (the default), n ≥ 0 that many bounces.
  void set_material_bounces(int bounces) { material_bounces_ = bounces; }
  // Whether relight() bounces the light of moved and added luminaires (the default) or, for a
  // first frame, lets the nearest stored luminaire's response stand in for their
  // interreflection (sources/luminaires/luminaire_lighting.h); layout_converged() says which
  // the last relight() gave.
  void set_layout_bounce(bool bounce) { lights_.luminaires().set_bounce_live(bounce); }
  bool layout_converged() const { return lights_.luminaires().converged(); }
  // Whether relight() computes only the sensor rows (RelighterSettings::sensors_only, where
  // the scene and the states so far allow it).
  bool sensors_only() const { return sensors_only_; }
  // Whether the last relight() gave the edited materials' converged light (true without edits).
  bool material_edit_final() const { return edit_final_ && !glossy_stale_; }
  // What each vertex reflects under the state's materials, 3 per vertex (ρE/π shading).
  std::span<const float> vertex_albedo() const { return vertex_albedo_; }

  // The scene's receivers, occluders and gather operator for light computed at run time;
  // null for a scene with no portals, emitters or movable objects until a state moves or adds a
  // luminaire or edits a material.
  const RuntimeScene* runtime_scene() const { return runtime_ ? &*runtime_ : nullptr; }
  // The sensors' importance when relight() reads the sensors alone through it, else null.
  std::shared_ptr<const SensorImportance> sensor_importance() const {
    return runtime_ ? runtime_->sensor_importance() : nullptr;
  }
  // The current shell of portal p (for renderers showing the view out of a window).
  const Shell& shell(std::size_t p) const { return lights_.portals().portal(p).shell; }
  // Wall time of the last shell update of portal p, seconds.
  double shell_seconds(std::size_t p) const { return lights_.portals().portal(p).seconds; }

  // The movable objects' term, when the scene has objects (their placed meshes, their
  // vertices' light, the occluders with them in place, the last frame's timings).
  const ObjectLighting* objects() const { return objects_ ? &*objects_ : nullptr; }
  // Objects the states so far placed through the room's surfaces, each once (then cleared).
  std::vector<std::string> take_object_warnings() {
    return objects_ ? objects_->take_warnings() : std::vector<std::string>{};
  }

  // The top-level environment's term, when the scene has one (its cuts, clusters and the
  // glossy reflection toward an eye: sources/environment/environment_lighting.h).
  const EnvironmentLighting* environment() const { return lights_.environment(); }
  // The same, for the glossy view's kept diffuse-layer sums (EnvironmentLighting::diffuse_layer).
  EnvironmentLighting* environment() { return lights_.environment(); }
  // Whether the environment's interreflection is added (the default) or its direct light
  // alone, as `relight reference --max-bounces 1` traces it.
  void set_environment_bounce(bool bounce);

  // The near-field emitters' term, when the scene has emitters (their last sampling).
  const EmitterLighting* emitters() const { return lights_.emitters(); }

  // The current photometry of luminaire j (as loaded for its state).
  const Distribution& distribution(std::size_t j) const {
    return lights_.luminaires().distribution(j);
  }
  // The luminaires' term.
  const LuminaireLighting& luminaires() const { return lights_.luminaires(); }

  std::size_t receivers() const { return transfer_.receivers; }
  // How many distribution changes were one moved curve control point, updated
  // incrementally (Dobashi et al. 1995's Eq. 21) instead of projected anew.
  std::size_t incremental_curve_updates() const {
    return lights_.luminaires().incremental_curve_updates();
  }
  // Bytes of stored transfer a relight() of every source reads.
  std::size_t transfer_bytes() const;
  // Bytes the last relight() read and wrote: the transfer of the sources it summed again,
  // and the partial sums and the output.
  std::size_t last_frame_bytes() const { return last_frame_bytes_; }

 private:
  static constexpr std::size_t kMaxTerms = 4;
  struct PartialSum {
    std::vector<float> values;  // 3 per receiver
    bool valid = false;
  };
  struct Term {
    LightTerm* source;
    PartialSum sums[2];  // [include_direct]
  };

  // out = Σ over terms of their sums for `slot` ([include_direct]), each term summed again
  // when its state changed; returns whether any was.
  bool sum_terms(std::size_t slot, std::span<float> out);
  // sum_terms for block b: the terms in `redo` summed again, then out over the block.
  void sum_block(std::size_t b, std::size_t slot, const std::array<bool, kMaxTerms>& redo,
                 std::span<float> out);
  // total = every term's light with direct, corrected by the material edit; returns whether
  // it changed since the last call.
  bool sum_edited(std::span<float> total);
  void set_materials(const std::vector<Material>& materials);
  // The glossy first bounce of the kinds' direct light for `materials` (the scene's or as
  // edited), bounced with `albedo` (3 per vertex); none when no material is glossy.
  void make_glossy_bounce(std::span<const Material> materials, std::span<const float> albedo);
  // Hands every kind the glossy first bounce (null: none).
  void set_glossy(const GlossyFirstBounce* glossy);
  // out += every kind's glossy first bounce.
  void add_glossy(std::span<float> out) const;
  // Marks term `source`'s partial sums stale.
  void invalidate(const LightTerm* source);
  void update_objects();

  TransferView transfer_;
  std::optional<RuntimeScene> runtime_;      // with portals, emitters, objects or glossy surfaces
  std::optional<MirrorReflection> mirrors_;  // the near-mirror planes of glossy_bounce_
  std::optional<GlossyFirstBounce> glossy_bounce_;  // with glossy surfaces
  LightTerms lights_;
  LightingState state_;
  std::vector<Term> terms_;  // one per kind, as lights_.all()
  std::optional<ObjectLighting> objects_;
  std::vector<float> room_light_;  // with objects: every term's light, direct included (E0)
  // Material edits: the bounce settings, the vertices' albedo under the state's materials,
  // and the edit's light (made on the first edit: it needs the stored gather operator).
  BounceSettings bounce_;
  std::vector<float> vertex_albedo_;  // 3 per vertex
  std::optional<AlbedoEdit> albedo_edit_;
  std::vector<float> edit_total_, edit_delta_;  // 3 per receiver
  bool edit_dirty_ = false, edit_final_ = true, edit_solved_ = false;
  bool glossy_dirty_ = false;  // the glossy first bounce was made again since the last relight
  // A material edit's first frame keeps the glossy first bounce of the materials before it
  // (made again, a bounce solve per luminaire, for the converged frame).
  bool glossy_stale_ = false;
  int material_bounces_ = -1;
  bool objects_dirty_ = true;    // placements or E0 changed since the objects' last update
  bool warm_sun_bounce_ = true;  // RelighterSettings::warm_sun_bounce
  bool sensors_only_ = false;    // RelighterSettings::sensors_only, as the scene allows it
  std::size_t last_frame_bytes_ = 0;
};

}  // namespace relight
