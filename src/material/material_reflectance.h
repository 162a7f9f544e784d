// What a scene material reflects, for the engine's diffuse transfer: the one place
// that turns a scene Material (scene/scene.h) into a surface model. A Lambertian material
// bounces with its albedo; a glossy one (the glTF metallic–roughness BRDF,
// material/metallic_roughness.h) bounces, until its glossy transfer is built, with its
// hemispherical albedo — the flux it reflects, spread as a diffuse surface would — and the
// reference tracer samples its true BRDF; window glass reflects nothing (the portal carries
// light through it). Pinned by tests/material/material_reflectance_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

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

// What a vertex of material m reflects where its base colour texture's value is `texture`
// (scene/surface_texture.h: glTF's baseColorFactor × texture; 1 where there is none).
inline Rgb bounce_albedo(const Material& m, Rgb texture) {
  Material textured = m;
  textured.albedo = m.albedo * texture;
  return bounce_albedo(textured);
}

// Per vertex v: the texture value (1 when `vertex_texture` is empty), from a prepared mesh's
// values or from 3 floats a vertex as stored.
inline Rgb vertex_texture_at(std::span<const Rgb> vertex_texture, std::size_t v) {
  return vertex_texture.empty() ? Rgb{1, 1, 1} : vertex_texture[v];
}
inline Rgb vertex_texture_at(std::span<const float> vertex_texture, std::size_t v) {
  if (vertex_texture.empty()) return {1, 1, 1};
  return {vertex_texture[3 * v], vertex_texture[3 * v + 1], vertex_texture[3 * v + 2]};
}

// The glossy materials of a material list (window glass never is): per material its index
// into `brdf`, or −1 when it is Lambertian or glass.
struct GlossyMaterials {
  std::vector<std::int32_t> index;
  std::vector<MetallicRoughness> brdf;
  bool empty() const { return brdf.empty(); }
};

inline GlossyMaterials glossy_materials(std::span<const Material> materials) {
  GlossyMaterials g;
  g.index.assign(materials.size(), -1);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (!materials[m].glossy || materials[m].portal) continue;
    g.index[m] = static_cast<std::int32_t>(g.brdf.size());
    g.brdf.push_back(metallic_roughness_of(materials[m]));
  }
  return g;
}

}  // namespace relight
