// The movable objects' run-time term (Iwasaki et al. 2007 is the paper): furniture that moves,
// turns, hides, casts shadows and bounces light, with no new precompute. The precomputed transfer
// is that of the empty room; this term adds, in every output, what the objects as placed change:
//
//   E = E0 + ΔE   at room receivers (E0: every other term's light, direct included),
//   E = E_q       at object vertices,
//
// solved as one linear system over room and object vertices. With the direct light
// ΔE_d (at room receivers, what the objects' shadows take away; at object vertices, their
// whole direct light — luminaires, suns and near-field emitters, traced exactly per receiver,
// through room and objects: sources/luminaires/luminaire_direct.h, sources/portals/portal_sun.h,
// sources/emitters/emitter_direct.h), the stored
// gather operator G of the empty room and the objects' rows C and H (object_transfer.h):
//
//   D  = ΔE_d + [C; H] · ρE0 + light through windows the objects gain or hide,
//   ΔE = D + [G + C; H] · ρ ΔE,
//
// (glossy object vertices reflecting the luminaires' part of ΔE_d by their BRDF toward each
// receiver in place of their diffuse stand-in: set_materials), the second bounced with
// engine/bounce_solver.h (warm-started from the last frame: an object
// dragged a little takes a bounce or two), the objects' rows applied once per sweep, rows
// that vertices take from proxies (receiver_proxies.h) spread from the proxies' values. E0 being
// the empty room's converged light (E0 = E0_d + G ρ E0), E0 + ΔE solves the room with its objects
// exactly as the stored estimator would. Sensors are gathered once from the converged light.
//
// Pinned by tests/runtime/object_transfer_test.cpp, tests/render/object_accuracy_test.cpp
// and tests/cli/glossy_object_test.cpp.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/runtime_scene.h"
#include "light/emitter_placement.h"
#include "material/metallic_roughness.h"
#include "math/placement.h"
#include "scene/scene.h"
#include "sources/luminaires/luminaire_direct.h"
#include "sources/objects/object_mesh.h"
#include "sources/objects/object_transfer.h"
#include "sources/portals/portal_sun.h"

namespace relight {

// The luminance seen through portal p's glass along a direction (the portal's shell with its
// tint; the sun behind clear glass excluded, since it is traced as direct light).
using GlassLuminance = std::function<Rgb(std::uint32_t portal, Vec3 direction)>;

// What the rest of the lighting gives the objects this frame.
struct ObjectLightInputs {
  std::span<const float> room;  // E0: 3 per room receiver, every other term, direct included
  std::span<const LuminaireLight> luminaires;
  // The same with more points on each luminous opening, for sensors (empty: `luminaires`).
  std::span<const LuminaireLight> sensor_luminaires;
  std::span<const PortalSun> suns;
  std::optional<SunGeometry> sun_geometry;   // the room's (set when there are suns)
  const PlacedEmitters* emitters = nullptr;  // the near-field emitters as placed; null: none
  GlassLuminance glass;                      // empty: windows show black
  // Direct light the objects change that another term computed with them in place (the top-level
  // environment's through its visibility cuts, sources/environment/environment_objects.h): at room
  // receivers what the objects take away or add (3 per receiver), at object vertices all of it
  // (3 per object vertex, PlacedObjects order); empty: none. Part of D, and kept with or without
  // direct light in every output: no renderer traces it per pixel.
  std::span<const float> extra_room, extra_objects;
  // The same for light that renderers tracing direct light per pixel trace too (the
  // environment's compact sources, sources/environment/compact_light.h): part of D and of ΔE_d, so
  // left out of the outputs without direct light. Empty: none.
  std::span<const float> traced_room, traced_objects;
};

struct ObjectTimings {
  double direct_seconds = 0, transfer_seconds = 0, bounce_seconds = 0;
  int bounces = 0;
  std::uint64_t rays = 0;  // of the last transfer
};

class ObjectLighting {
 public:
  // `room` must have its gather operator (RuntimeScene::can_bounce) and outlive this; `meshes`
  // are the scene's objects as prepared (TransferView::objects), every one where the scene
  // placed it.
  ObjectLighting(const RuntimeScene& room, std::vector<ObjectMesh> meshes,
                 ObjectTransferSettings settings = {});

  // Places the objects (scene order); returns whether any placement changed.
  bool set_state(std::span<const MovablePlacement> placements);
  // Recomputes ΔE and the objects' light: the transfer where objects moved since the last
  // update (object_transfer.h retrace_object_transfer); the luminaires' shadow factors where
  // a moved object may shadow or a luminaire moved or changed its opening (a dimmer, colour or
  // aim only re-evaluates them); the suns' and emitters' direct light wherever an object may
  // shadow when `light_changed` (any other term's light, E0, changed) or else only where a
  // moved object may; and the bounce always.
  void update(const ObjectLightInputs& inputs, bool light_changed);
  // Live material edits: the room's vertices reflect `room_albedo` (3 per vertex) and the
  // objects' vertices their materials' (material/material_reflectance.h; objects from files
  // without their vertices' materials keep theirs).
  void set_albedo(std::span<const float> room_albedo, std::span<const Material> materials);
  // The objects' glossy materials (the scene's or a state's): an object vertex of a glossy
  // material reflects the luminaires' direct light toward each receiver by its BRDF in the
  // objects' rows (what the diffuse stand-in reflected taken out, as the room's glossy first
  // bounce does: engine/glossy_first_bounce.h); the rest of its light as the stand-in.
  void set_materials(std::span<const Material> materials);

  // Direct light alone (`relight render --max-bounces 1`, like the reference's): ΔE = D = the
  // direct light the objects change, nothing gathered or bounced. Default false.
  void set_direct_only(bool direct_only) { direct_only_ = direct_only; }
  // Adds ΔE to `out` (3 per room receiver); without direct light, ΔE less ΔE_d (what
  // renderers that trace direct light per pixel, through the objects, still need).
  void add_to_room(std::span<float> out, bool include_direct) const;
  // The objects' vertices' irradiance, 3 per vertex (PlacedObjects order; 0 when hidden).
  std::span<const float> irradiance(bool include_direct) const {
    return include_direct ? object_total_ : object_indirect_;
  }
  const PlacedObjects& placed() const { return placed_; }
  const std::vector<ObjectMesh>& meshes() const { return meshes_; }
  // The room and the placed objects, blocking light together.
  Occluders occluders() const { return {room_->occluders(), &placed_.tracer}; }
  const ObjectTimings& timings() const { return timings_; }
  // Names of objects a state placed through the room's surfaces (allowed: light then passes
  // as the geometry says), each listed once, the first time; take_warnings() empties the list.
  std::vector<std::string> take_warnings() { return std::exchange(warnings_, {}); }
  const ObjectTransfer& transfer() const { return transfer_; }

 private:
  void trace_direct(const ObjectLightInputs& inputs, bool all);
  // out (3 per solver row: room vertices, object vertices, sensors) += [C; H] · light (3 per
  // unified column), proxies included; with `sensors_only`, at the sensors' rows alone.
  void apply_object_rows(std::span<const float> light, std::span<float> out, bool sensors_only);
  // out += the light through windows that the objects' rows gain or hide.
  void add_glass_light(const GlassLuminance& glass, std::span<float> out);
  // out += what glossy object vertices reflect of the luminaires toward each receiver by
  // their BRDF, less what their diffuse stand-in reflects of it (set_materials).
  void add_glossy_reflection(const ObjectLightInputs& in, std::span<float> out);
  // out (3 per solver row) += row_sum(rows, i, transfer row, sum) over every object row, rows
  // of vertices that take them from proxies spread from the proxies' sums.
  template <typename RowSum>
  void for_object_rows(const RowSum& row_sum, std::span<float> out);

  const RuntimeScene* room_;
  ObjectTransferSettings settings_;
  std::vector<ObjectMesh> meshes_;
  std::vector<MovablePlacement> placements_;
  PlacedObjects placed_;
  ObjectTransfer transfer_;
  bool transfer_valid_ = false, direct_valid_ = false;
  // Objects moved since the last update, and every object as placed then (set while any is).
  std::vector<std::uint32_t> moved_;
  std::optional<PlacedObjects> lit_;
  std::vector<float> albedo_;  // 3 per unified row that reflects: room vertices, objects
  std::vector<std::optional<MetallicRoughness>> object_brdf_;  // per object vertex, if glossy
  bool glossy_ = false;                                        // any object vertex glossy
  std::vector<float> direct_;  // ΔE_d: 3 per unified row (room vertices, objects, sensors)
  // Per luminaire: where its shadow rays started from and ended on, and per unified row what
  // the objects change in its geometry factor (luminaire_direct.h direct_factor), the empty
  // room's factor (NaN until traced; 0 once its visible opening points are kept) and the
  // opening points the empty room leaves visible (only those are traced against the objects).
  struct LuminaireShadows {
    Vec3 position;
    std::vector<Vec3> opening, sensor_opening;
    std::vector<float> factor, room_factor;
    std::vector<OpeningMask> room_visible;
  };
  std::vector<LuminaireShadows> luminaire_shadows_;
  std::vector<float> other_direct_;         // the suns' and emitters' part of ΔE_d, likewise
  std::vector<std::uint8_t> retraced_;      // per unified row: traced again this update
  std::vector<float> source_;               // D, likewise
  std::vector<float> indirect_;             // the bounce, likewise
  std::vector<float> proxy_values_;         // 3 per proxy per layer: each object's cones, the base
  std::vector<std::uint8_t> base_proxied_;  // per unified column: base row from proxies
  // Per layer, per unified column: whether that row is taken from proxies.
  std::vector<std::span<const std::uint8_t>> proxy_layers_;
  std::vector<float> static_light_;   // ρE0, 3 per unified column
  std::vector<float> object_gather_;  // [C; H] · ρΔE this sweep, 3 per unified row
  bool warm_ = false;
  bool direct_only_ = false;
  std::vector<float> room_delta_, room_delta_direct_;  // 3 per room receiver
  std::vector<float> object_total_, object_indirect_;  // 3 per object vertex
  ObjectTimings timings_;
  std::vector<bool> warned_;  // per object
  std::vector<std::string> warnings_;
};

}  // namespace relight
