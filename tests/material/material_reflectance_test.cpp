// What a scene material bounces in the diffuse transfer (material/material_reflectance.h): a
// Lambertian material its albedo, window glass nothing, a glossy one its hemispherical albedo —
// the cosine-weighted mean over incident directions of the BRDF's directional albedo, checked
// here against quadrature of the BRDF itself to 2e-3 for metals and dielectrics, rough and
// polished.
#include <cmath>

#include <gtest/gtest.h>

#include "material/material_reflectance.h"

namespace relight {
namespace {

// 2 ∫ A(μ) μ dμ with A(μ) = ∫ f cos θ_l dω_l by the reflection quadrature (midpoints in μ).
Rgb quadrature_hemispherical_albedo(const MetallicRoughness& m) {
  constexpr int kMu = 48;
  Rgb mean;
  for (int i = 0; i < kMu; ++i) {
    const double mu = (i + 0.5) / kMu;
    const Vec3 v{std::sqrt(1 - mu * mu), 0, mu};
    Rgb albedo;
    for_each_reflection_node(v, std::max(m.roughness * m.roughness, 1e-4), 48,
                             [&](Vec3 l, double w) {
                               albedo += metallic_roughness_brdf(m, {0, 0, 1}, l, v) * (l.z * w);
                             });
    mean += albedo * (2 * mu / kMu);
  }
  return mean;
}

TEST(MaterialReflectance, LambertianBouncesItsAlbedoAndGlassNothing) {
  const Material paint{"paint", {0.6, 0.5, 0.4}};
  EXPECT_EQ(bounce_albedo(paint), paint.albedo);
  Material glass{"glass", {0.6, 0.5, 0.4}};
  glass.portal = true;
  EXPECT_EQ(bounce_albedo(glass), Rgb{});
}

TEST(MaterialReflectance, GlossyBouncesItsHemisphericalAlbedoWithin2e3OfQuadrature) {
  for (const double metallic : {0.0, 1.0}) {
    for (const double roughness : {0.2, 0.3, 0.6, 1.0}) {
      Material m{"m", {0.9, 0.5, 0.2}};
      m.glossy = true;
      m.metallic = metallic;
      m.roughness = roughness;
      const Rgb a = bounce_albedo(m), q = quadrature_hemispherical_albedo(metallic_roughness_of(m));
      EXPECT_NEAR(a.r, q.r, 2e-3) << metallic << " " << roughness;
      EXPECT_NEAR(a.g, q.g, 2e-3) << metallic << " " << roughness;
      EXPECT_NEAR(a.b, q.b, 2e-3) << metallic << " " << roughness;
      EXPECT_LE(max_component(a), 1.0);
    }
  }
  // A white dielectric reflects everything (the coupled diffuse layer, the white furnace).
  Material white{"white", {1, 1, 1}};
  white.glossy = true;
  white.roughness = 0.4;
  EXPECT_NEAR(bounce_albedo(white).g, 1.0, 2e-3);
}

}  // namespace
}  // namespace relight
