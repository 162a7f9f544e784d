#include "runtime/direct_light.h"

namespace relight {

DirectLight::DirectLight(RelitScene& scene, int opening_samples) {
  const Relighter& lit = scene.relighter();
  const ObjectLighting* objects = lit.objects();
  const Occluders occluders =
      objects != nullptr ? objects->occluders() : Occluders(scene.opaque_tracer());
  for (const LightTerm* light : lit.lights()) {
    kinds_.push_back(light->direct_lights(occluders, opening_samples));
  }
}

Rgb DirectLight::irradiance_at(Vec3 p, Vec3 n) const {
  Rgb e;
  for (const auto& lights : kinds_) e += lights->irradiance_at(p, n);
  return e;
}

}  // namespace relight
