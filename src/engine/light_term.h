// The contract of a kind of light at run time: everything the run time needs to know of one kind
// (the luminaires, the portals with their suns, the near-field emitters, the top-level
// environment), in the scene format's words. A kind takes its part of the lighting state, keeps
// its weighted sum over the stored transfer (light is linear: every change is a weight on
// precomputed responses), adds its glossy first reflection where it has one, and gives the exact
// direct light of its lights at any point with the occluders of the moment. The Relighter
// (runtime/relighter.h) holds the closed list of kinds (sources/light_terms.h) and knows them
// through this contract alone; docs/architecture.md walks through adding a kind.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string_view>

#include "engine/glossy_first_bounce.h"
#include "engine/transfer_blocks.h"
#include "light/lighting_state.h"
#include "light/seen_light.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

// visit(kind, name, light): one light as a point sees it, with its kind and name (the
// luminaire's, the portal's for a sun, the emitter's; "" for the environment's sources).
using SeenLightVisit = std::function<void(LightKind, std::string_view, const SeenLight&)>;

// A kind's lights as one lighting state sets them, prepared to give their exact direct light at
// any point (each kind computes it in one place: its *_seen_from and *_irradiance), shadowed by
// the occluders it was made with.
class DirectLights {
 public:
  virtual ~DirectLights() = default;
  // Σ over its lights of the exact direct irradiance at p (unit normal n), lx per channel.
  virtual Rgb irradiance_at(Vec3 p, Vec3 n) const = 0;
  // Each of its lights as p (unit normal n) sees it, in scene order. `with_luminance`: also what
  // an eye at p sees of it (SeenLight::luminance, solid_angle), which costs a shadow ray or more
  // a light.
  virtual void for_each_at(Vec3 p, Vec3 n, bool with_luminance,
                           const SeenLightVisit& visit) const = 0;
};

class LightTerm {
 public:
  virtual ~LightTerm() = default;
  // The scene format's word for the kind: "luminaires", "portals", "emitters", "environment".
  virtual std::string_view kind() const = 0;
  // Takes the kind's part of `state`; returns whether its sum changed. What the change costs
  // beyond weights (a sampling, a bounce) may wait for update().
  virtual bool set_state(const LightingState& state) = 0;
  // Makes what set_state left for later; the Relighter calls it before summing. Returns whether
  // that changed the term's sum since set_state (a refinement its first sum did not have).
  virtual bool update() { return false; }
  // acc_c[i] += the term's irradiance (lx, RGB) at receivers [block · kBlock, …). Without
  // direct light: only what renderers that evaluate direct light per pixel still need
  // (Relighter::relight).
  virtual void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const = 0;
  // Bytes of stored transfer (and per-receiver run-time fields) one full sum reads.
  virtual std::size_t transfer_bytes() const = 0;
  // The glossy surfaces' first reflection of the kind's direct light
  // (engine/glossy_first_bounce.h), made again when its light changes; null: none. `glossy`
  // must outlive the term. A kind whose direct light glossy surfaces do not reflect apart
  // (its glossy light is in its own sum) ignores it.
  virtual void set_glossy(const GlossyFirstBounce* /*glossy*/) {}
  // out (3 per receiver) += that glossy reflection. Not part of add_block: it is bounced with
  // the materials as edited (the Relighter adds it after a material edit's correction).
  virtual void add_glossy(std::span<float> /*out*/) const {}
  // The kind's lights as the current state sets them, shadowed by `occluders` (the room's, or
  // the room's with the movable objects in place). `opening_samples`: points on each luminous
  // area for its visibility (a luminaire's opening, an emitter's triangles).
  virtual std::unique_ptr<const DirectLights> direct_lights(const Occluders& occluders,
                                                            int opening_samples) const = 0;
};

}  // namespace relight
