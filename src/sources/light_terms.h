// The closed list of the kinds of light at run time, each behind the contract of
// engine/light_term.h: the luminaires, the portals (the sky through their shells and their exact
// suns), the near-field emitters when the scene has any and the top-level environment when it
// has one, made from a scene's stored transfer. all() is the list the Relighter iterates, in the
// order their sums are added; the typed members are for what reads a kind's own figures (its
// timings, a luminaire's photometry, a portal's shell) and for the movable objects, whose
// shadows each kind traces with caches of its own (sources/objects/object_lighting.h).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "engine/light_term.h"
#include "engine/runtime_scene.h"
#include "math/sh_window.h"
#include "scene/scene.h"
#include "sources/emitters/emitter_lighting.h"
#include "sources/environment/environment_lighting.h"
#include "sources/luminaires/luminaire_lighting.h"
#include "sources/portals/portal_lighting.h"
#include "sources/transfer_view.h"

namespace relight {

struct LightTermSettings {
  ShWindow window = ShWindow::kSigma;  // applied to the SH weights of every luminaire
  EmitterLightingSettings emitters;    // sampling of near-field emitters
  SunBounce sun_bounce = SunBounce::kWarm;
  // The top-level environment's interreflection added; false: its direct light alone.
  bool environment_bounce = true;
};

class LightTerms {
 public:
  // Every kind lit as the scene sets it. `transfer`, `runtime` and `scene` must outlive the
  // terms; `runtime` may be null only for a scene without portals, emitters and environment.
  LightTerms(const TransferView& transfer, const RuntimeScene* runtime, const Scene& scene,
             const LightTermSettings& settings);
  LightTerms(const LightTerms&) = delete;  // all() points into the terms
  LightTerms& operator=(const LightTerms&) = delete;

  // Every kind the scene has, in the order their sums are added.
  std::span<LightTerm* const> all() const { return all_; }

  LuminaireLighting& luminaires() { return *luminaires_; }
  const LuminaireLighting& luminaires() const { return *luminaires_; }
  PortalSetLighting& portals() { return *portals_; }
  const PortalSetLighting& portals() const { return *portals_; }
  EmitterLighting* emitters() const { return emitters_.get(); }            // null: no emitters
  EnvironmentLighting* environment() const { return environment_.get(); }  // null: none

 private:
  std::unique_ptr<LuminaireLighting> luminaires_;
  std::unique_ptr<PortalSetLighting> portals_;
  std::unique_ptr<EmitterLighting> emitters_;
  std::unique_ptr<EnvironmentLighting> environment_;
  std::vector<LightTerm*> all_;
};

}  // namespace relight
