// The exact direct light of every kind at a point, as the lighting state of a RelitScene sets it
// and shadowed by what stands there at the moment (the room, and the movable objects where the
// state places them): the luminaires through their openings, the suns behind clear glass, the
// near-field emitters and a top-level environment's compact sources (its sun). Each kind computes
// it in one place (its *_seen_from: sources/luminaire/luminaire_direct.h,
// sources/portal/portal_sun.h, sources/nearfield/emitter_direct.h, sources/cuts/compact_light.h);
// this gathers them for whoever shows direct light exactly: the per-pixel and glossy renderers
// (render/relit_scene_image.cpp) and glare (render/glare.h). Built for one state: build it again
// after RelitScene::apply.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "light/seen_light.h"
#include "runtime/relit_scene.h"
#include "sources/cuts/compact_light.h"
#include "sources/luminaire/luminaire_direct.h"
#include "sources/nearfield/emitter_direct.h"
#include "sources/portal/portal_sun.h"

namespace relight {

enum class LightKind { kLuminaire, kSun, kEmitter, kEnvironment };

// "luminaire", "sun", "emitter", "environment": the words of the scene format.
std::string_view light_kind_name(LightKind kind);

class DirectLight {
 public:
  // `opening_samples`: points on each luminaire's luminous opening for its visibility.
  explicit DirectLight(RelitScene& scene, int opening_samples = 16);

  // Σ over every light of its exact direct irradiance at p (unit normal n), lx per channel.
  Rgb irradiance_at(Vec3 p, Vec3 n) const;

  // Each light as p (unit normal n) sees it, with its kind and name (the luminaire's, the
  // portal's for a sun, the emitter's; "" for the environment's sources), in that order of
  // kinds and the scene's order within each. `with_luminance`: also what an eye at p sees of
  // it (SeenLight::luminance, solid_angle), which costs a shadow ray or more a light.
  template <typename Visit>
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance, const Visit& visit) const;

 private:
  const Scene& scene_;
  const Relighter& lit_;
  Occluders occluders_;
  std::vector<LuminaireLight> lights_;
  std::vector<LuminousOpening> openings_;  // per luminaire (luminaire_opening)
  std::optional<SunGeometry> sun_geometry_;
  std::span<const CompactSource> compact_;  // the top-level environment's (none without one)
};

template <typename Visit>
void DirectLight::for_each_at(Vec3 p, Vec3 n, bool with_luminance, const Visit& visit) const {
  for (std::size_t j = 0; j < lights_.size(); ++j) {
    visit(LightKind::kLuminaire, std::string_view(scene_.luminaires[j].name),
          luminaire_seen_from(occluders_, lights_[j], openings_[j], p, n, with_luminance));
  }
  if (sun_geometry_) {
    for (const PortalSun& sun : lit_.suns()) {
      visit(LightKind::kSun, std::string_view(scene_.portals.at(sun.portal).name),
            sun_seen_from(*sun_geometry_, sun, p, n, with_luminance));
    }
  }
  if (const EmitterLighting* emitters = lit_.emitters(); emitters != nullptr) {
    for (std::size_t k = 0; k < scene_.emitters.size(); ++k) {
      visit(LightKind::kEmitter, std::string_view(scene_.emitters[k].name),
            emitter_seen_from(emitters->placed(), k, &occluders_, p, n, with_luminance));
    }
  }
  const Vec3 origin = offset_from_surface(p, n);
  for (const CompactSource& source : compact_) {
    visit(LightKind::kEnvironment, std::string_view(),
          compact_seen_from(occluders_, source, origin, n, with_luminance));
  }
}

}  // namespace relight
