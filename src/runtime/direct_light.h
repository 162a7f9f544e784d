// The exact direct light of every kind at a point, as the lighting state of a RelitScene sets it
// and shadowed by what stands there at the moment (the room, and the movable objects where the
// state places them): each kind's lights through the contract's direct_lights
// (engine/light_term.h), in the order of the Relighter's kinds — the luminaires through their
// openings, the suns behind clear glass, the near-field emitters, a top-level environment's
// compact sources (its sun). For whoever shows direct light exactly: the per-pixel and glossy
// renderers (render/relit_scene_image.cpp) and glare (render/glare.h). Built for one state:
// build it again after RelitScene::apply.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "engine/light_term.h"
#include "light/seen_light.h"
#include "runtime/relit_scene.h"

namespace relight {

class DirectLight {
 public:
  // `opening_samples`: points on each luminous area (a luminaire's opening, an emitter's
  // triangles) for its visibility.
  explicit DirectLight(RelitScene& scene, int opening_samples = 16);

  // Σ over every light of its exact direct irradiance at p (unit normal n), lx per channel.
  Rgb irradiance_at(Vec3 p, Vec3 n) const;

  // Each light as p (unit normal n) sees it, with its kind and name (the luminaire's, the
  // portal's for a sun, the emitter's; "" for the environment's sources), kind by kind and in
  // the scene's order within each. `with_luminance`: also what an eye at p sees of it
  // (SeenLight::luminance, solid_angle), which costs a shadow ray or more a light.
  template <typename Visit>
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance, const Visit& visit) const {
    const SeenLightVisit call = std::cref(visit);
    for (const auto& lights : kinds_) lights->for_each_at(p, n, with_luminance, call);
  }

 private:
  std::vector<std::unique_ptr<const DirectLights>> kinds_;
};

}  // namespace relight
