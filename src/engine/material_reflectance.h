// What a scene material reflects, for the engine's diffuse transfer (issue 13): the one place
// that turns a scene Material (scene/scene.h) into a surface model. A Lambertian material
// bounces with its albedo; a glossy one (the glTF metallic–roughness BRDF,
// material/metallic_roughness.h) bounces, until its glossy transfer is built, with its
// hemispherical albedo — the flux it reflects, spread as a diffuse surface would — and the
// reference tracer samples its true BRDF; window glass reflects nothing (the portal carries
// light through it). Pinned by tests/engine/material_reflectance_test.cpp.
#pragma once

#include "material/metallic_roughness.h"
#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

inline MetallicRoughness metallic_roughness_of(const Material& m) {
  return {m.albedo, m.metallic, m.roughness};
}

inline Rgb bounce_albedo(const Material& m) {
  if (m.portal) return {};
  return m.glossy ? hemispherical_albedo(metallic_roughness_of(m)) : m.albedo;
}

}  // namespace relight
