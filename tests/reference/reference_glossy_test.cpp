// The reference tracer on glossy surfaces (reference/reference_tracer.h,
// reference/reference_weight.h), against closed forms of single reflection:
//  - a point source over a glossy plane: the luminance seen is f(l, v)·I·cos θ/d² exactly
//    (next-event estimation with the BRDF; nothing else reflects) — within 0.5 %;
//  - a skylight of uniform luminance L over a glossy plane: L ∫ f(l, v) cos θ_l dω over the
//    skylight, by quadrature over its area — within 2 % — for a metal and a satin dielectric at
//    roughness 0.1–0.3, where the skylight's area samples and the BRDF samples that leave through
//    it share the estimate (multiple importance sampling: a weight that does not sum to 1, or a
//    direction counted twice, shows here).
#include <cmath>

#include <gtest/gtest.h>

#include "light/environment_map_io.h"
#include "light/luminaire_frame.h"
#include "material/metallic_roughness.h"
#include "reference/reference_tracer.h"
#include "scene/scene_loader.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

using nlohmann::json;

constexpr Vec3 kEye{2.5, 1.8, 0.3};
constexpr Vec3 kTarget{-0.4, 0, 0.1};  // on the floor

json floor_scene(const json& floor_material) {
  return {{"materials", {{"floor", floor_material}, {"glass", {{"portal", true}}}}},
          {"geometry",
           {{{"type", "quad"},
             {"corner", {-6, 0, -6}},
             {"u", {0, 0, 12}},
             {"v", {12, 0, 0}},
             {"material", "floor"}}}},
          {"cameras",
           {{{"name", "c"},
             {"eye", {kEye.x, kEye.y, kEye.z}},
             {"target", {kTarget.x, kTarget.y, kTarget.z}},
             {"fov_deg", 0.05}}}}};
}

// The luminance of the one pixel looking at kTarget.
Rgb pixel(const json& document, int spp) {
  const Scene scene = scene_from_json(document, "glossy.json");
  PreparationSettings preparation;
  preparation.max_edge = 0;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  std::vector<Environment> environments;
  for (const Portal& p : scene.portals) environments.push_back(load_environment(p.environment));
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  const ReferenceScene ref =
      make_reference_scene(scene, mesh, traced, luminaires, std::move(environments));
  ReferenceSettings settings;
  settings.spp = spp;
  settings.seed = 11;
  settings.progress = false;
  return reference_render(make_pinhole_camera(scene.cameras.at(0), 1, 1), ref, settings)
      .luminance.pixels.at(0);
}

MetallicRoughness surface(Rgb albedo, double metallic, double roughness) {
  return {albedo, metallic, roughness};
}

json material_json(const MetallicRoughness& m) {
  return {{"albedo", {m.albedo.r, m.albedo.g, m.albedo.b}},
          {"metallic", m.metallic},
          {"roughness", m.roughness}};
}

TEST(ReferenceGlossy, PointSourceOverAGlossyPlaneIsFTimesICosOverDSquaredWithinHalfAPercent) {
  const Vec3 light{0.2, 2.2, -0.3};
  const double intensity = 1000;
  for (const MetallicRoughness& m :
       {surface({0.9, 0.8, 0.6}, 1, 0.3), surface({0.5, 0.3, 0.2}, 0, 0.2)}) {
    json scene = floor_scene(material_json(m));
    scene["luminaires"] = {{{"name", "point"},
                            {"position", {light.x, light.y, light.z}},
                            {"distribution", {{"type", "isotropic"}, {"candela", intensity}}}}};
    const Rgb seen = pixel(scene, 16);
    const Vec3 n{0, 1, 0}, l = normalize(light - kTarget), v = normalize(kEye - kTarget);
    const double d2 = dot(light - kTarget, light - kTarget);
    const Rgb expected = metallic_roughness_brdf(m, n, l, v) * (intensity * dot(n, l) / d2);
    EXPECT_NEAR(seen.r, expected.r, 5e-3 * expected.r) << m.metallic << " " << m.roughness;
    EXPECT_NEAR(seen.g, expected.g, 5e-3 * expected.g) << m.metallic << " " << m.roughness;
    EXPECT_NEAR(seen.b, expected.b, 5e-3 * expected.b) << m.metallic << " " << m.roughness;
  }
}

TEST(ReferenceGlossy, SkylightOverAGlossyPlaneMatchesQuadratureWithinTwoPercent) {
  // A 1.2 × 1.2 m skylight 2.5 m up around the mirror direction of the eye at kTarget (x ≈
  // −4.4, z ≈ −0.2), so that the narrow lobes see it; the sky above it uniform.
  const double luminance = 3000, size = 1.2, height = 2.5;
  const Vec3 corner{-5.0, height, -0.8};
  for (const MetallicRoughness& m :
       {surface({0.9, 0.9, 0.9}, 1, 0.1), surface({0.9, 0.9, 0.9}, 1, 0.3),
        surface({0.5, 0.5, 0.5}, 0, 0.2)}) {
    json scene = floor_scene(material_json(m));
    scene["geometry"].push_back({{"type", "quad"},
                                 {"corner", {corner.x, corner.y, corner.z}},
                                 {"u", {size, 0, 0}},
                                 {"v", {0, 0, size}},
                                 {"material", "glass"}});
    scene["portals"] = {{{"name", "skylight"},
                         {"material", "glass"},
                         {"environment", {{"type", "uniform"}, {"luminance", luminance}}}}};
    const double seen = pixel(scene, 20000).g;
    // L ∫ f cos θ_x cos θ_y / d² dA over the skylight (midpoint rule, 600² cells).
    constexpr int kCells = 600;
    const Vec3 n{0, 1, 0}, v = normalize(kEye - kTarget);
    double expected = 0;
    const double cell = size / kCells;
    for (int i = 0; i < kCells; ++i) {
      for (int j = 0; j < kCells; ++j) {
        const Vec3 y = corner + Vec3{(i + 0.5) * cell, 0, (j + 0.5) * cell};
        const Vec3 d = y - kTarget;
        const double d2 = dot(d, d);
        const Vec3 l = d / std::sqrt(d2);
        expected += metallic_roughness_brdf(m, n, l, v).g * l.y * l.y / d2 * cell * cell;
      }
    }
    expected *= luminance;
    std::printf(
        "skylight over metallic %.0f, roughness %.1f: reference %.2f, quadrature %.2f cd/m2\n",
        m.metallic, m.roughness, seen, expected);
    EXPECT_NEAR(seen, expected, 0.02 * expected) << m.metallic << " " << m.roughness;
  }
}

}  // namespace
}  // namespace relight
