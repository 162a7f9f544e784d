// The near-field emitters' run-time term (Sun 2005 Fig. 3.1): for a placement of the emitters, the
// incident radiance is sampled adaptively over the receiver BVH and reconstructed at every receiver
// (sources/emitters/nearfield_lighting.h) and shaded with the stored shadowed transfer,
// E_r = Σ_k t_rk · l_rk; at sensors the exact area-light integral
// (sources/emitters/emitter_direct.h) replaces it. With the stored gather operator this direct
// field bounces through the scene (engine/bounce_solver.h, the precompute's own solver): the
// interreflection of light that differs from surface to surface, which no precomputed SH response
// can hold for emitters this near.
// Sampled and bounced again only when an emitter's state changes.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/light_term.h"
#include "engine/runtime_scene.h"
#include "light/emitter_placement.h"
#include "light/emitter_state.h"
#include "scene/scene.h"
#include "sources/emitters/nearfield_lighting.h"
#include "sources/emitters/nearfield_transfer_view.h"
#include "trace/ray_tracer.h"

namespace relight {

struct EmitterLightingSettings {
  double epsilon = 0.01;              // the adaptive sampler's bound (relight nearfield's default)
  std::size_t max_samples = 4096;     // its cap
  int face_size = 16;                 // cubemap texels per face side at each sample
  int visibility_samples = 16;        // points per emitter triangle for exact direct shadows
  int bounce_visibility_samples = 4;  // the same for the light the vertices reflect
  // What the vertices reflect: the hat means' quadrature (engine/runtime_scene.h); 0: one
  // point per triangle corner, exact for light linear over the triangle.
  int hat_subdivision = 0;
};

class EmitterLighting : public LightTerm {
 public:
  // Lit as the scene sets every emitter (after update()). `runtime` is the scene's receivers,
  // occluders and gather operator (bounced through when the precompute kept it).
  EmitterLighting(const NearfieldTransferView& transfer, const RuntimeScene& runtime,
                  const Scene& scene, EmitterLightingSettings settings = {});

  std::string_view kind() const override { return "emitters"; }
  // Applies the emitters' states (scene order). Returns whether the term's sum changed; the
  // sampling and bounce wait for update().
  bool set_state(std::span<const EmitterState> states);
  bool set_state(const LightingState& state) override { return set_state(state.emitters); }
  // Samples and bounces the current state's light if it changed since (the Relighter calls
  // it before summing; add_block reads what it made).
  bool update() override;

  void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const override;
  std::size_t transfer_bytes() const override;
  // Each emitter as placed, its triangles' visible fractions from `opening_samples` points
  // each (sources/emitters/emitter_direct.h).
  std::unique_ptr<const DirectLights> direct_lights(const Occluders& occluders,
                                                    int opening_samples) const override;

  // The emitters as the current state places them, and the static scene that shadows them:
  // for exact direct light per pixel.
  const PlacedEmitters& placed() const { return placed_; }
  const RayTracer& occluders() const { return runtime_->occluders(); }
  // The last sampling (samples taken and seconds) and the wall time of its bounce.
  const NearfieldResult& last_sampling() const { return sampling_; }
  double last_bounce_seconds() const { return bounce_seconds_; }

 private:
  void relight();
  bool current_ = false;  // total_ and indirect_ are of states_

  const NearfieldTransferView* transfer_;
  const RuntimeScene* runtime_;
  const Scene* scene_;
  EmitterLightingSettings settings_;
  NearfieldScene nearfield_;
  std::vector<EmitterState> states_;
  PlacedEmitters placed_;
  NearfieldResult sampling_;
  bool bounces_ = false;  // with "nearfield_interreflection"
  double bounce_seconds_ = 0;
  std::vector<float> total_;     // 3 per receiver: direct + interreflected
  std::vector<float> indirect_;  // 3 per receiver: interreflected only
};

}  // namespace relight
