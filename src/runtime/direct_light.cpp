#include "runtime/direct_light.h"

namespace relight {

std::string_view light_kind_name(LightKind kind) {
  switch (kind) {
    case LightKind::kLuminaire:
      return "luminaire";
    case LightKind::kSun:
      return "sun";
    case LightKind::kEmitter:
      return "emitter";
    case LightKind::kEnvironment:
      return "environment";
  }
  return "";
}

namespace {

Occluders occluders_of(RelitScene& scene) {
  const ObjectLighting* objects = scene.relighter().objects();
  return objects != nullptr ? objects->occluders() : Occluders(scene.opaque_tracer());
}

}  // namespace

DirectLight::DirectLight(RelitScene& scene, int opening_samples)
    : scene_(scene.scene()),
      lit_(scene.relighter()),
      occluders_(occluders_of(scene)),
      lights_(lit_.luminaires().lights(scene_.luminaires, opening_samples)) {
  openings_.reserve(lights_.size());
  for (std::size_t j = 0; j < lights_.size(); ++j) {
    openings_.push_back(
        luminaire_opening(scene_.luminaires[j], lights_[j].distribution->opening()));
  }
  // A scene without windows has no suns and no sun geometry; with objects, they shadow the sun.
  if (!lit_.suns().empty()) {
    sun_geometry_.emplace(lit_.sun_geometry());
    sun_geometry_->occluders = occluders_;
  }
  if (const EnvironmentLighting* env = lit_.environment(); env != nullptr) {
    compact_ = env->compact_sources();
  }
}

Rgb DirectLight::irradiance_at(Vec3 p, Vec3 n) const {
  Rgb e = luminaire_direct_irradiance(occluders_, lights_, p, n);
  if (sun_geometry_) e += sun_irradiance(*sun_geometry_, lit_.suns(), p, n);
  e += compact_irradiance(occluders_, compact_, offset_from_surface(p, n), n);
  if (const EmitterLighting* emitters = lit_.emitters(); emitters != nullptr) {
    e += emitter_direct_irradiance(emitters->placed(), &occluders_, p, n);
  }
  return e;
}

}  // namespace relight
