// The glossy view's kept diffuse-layer sums (sources/cuts/environment_lighting.h diffuse_layer,
// material/metallic_roughness.h diffuse_of_sums): at every glossy vertex of a lacquered floor
// and a lacquered movable box under a sky with a sun, the specular lobe summed at each node plus
// the diffuse layer from the kept sums equals the whole BRDF summed at each node, to 1e-9 —
// with the sums made for the light as it was, then kept, then made again after the sun turns,
// for another roughness, and (the box's) after the box moves and turns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "material/metallic_roughness.h"
#include "runtime/lighting_state.h"
#include "runtime/relit_scene.h"
#include "sources/cuts/environment_lighting.h"
#include "support/precomputed_file.h"

namespace relight {
namespace {

nlohmann::json lacquered_showroom() {
  return nlohmann::json::parse(R"({
    "materials": {
      "lacquer": {"albedo": [0.6, 0.3, 0.2], "metallic": 0, "roughness": 0.3}
    },
    "geometry": [
      {"type": "quad", "corner": [-2, 0, -2], "u": [0, 0, 4], "v": [4, 0, 0], "material": "lacquer"}
    ],
    "objects": [
      {"name": "box", "geometry": [{"type": "box", "min": [-0.3, 0, -0.3], "max": [0.3, 0.5, 0.3],
                                    "material": "lacquer"}]}
    ],
    "environment": {"type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
                    "sun": {"azimuth_deg": 225, "altitude_deg": 40}, "sun_illuminance": 60000},
    "precompute": {"max_edge": 0.4, "gather_rays": 16,
                   "cuts": {"directions": 2048, "sphere_count": 4, "sphere_points": 8}}
  })");
}

// The largest difference over the room's receivers and the box's vertices between the whole
// BRDF toward `eye` summed at each node and the specular lobe plus the kept diffuse layer, at
// `roughness`, relative to the largest whole value; `whole` counts the vertices with light.
double largest_difference(RelitScene& relit, Vec3 eye, double roughness, int& lit) {
  EnvironmentLighting& env = *relit.relighter().environment();
  const PlacedObjects& placed = relit.relighter().objects()->placed();
  env.prepare_view_cache(placed.vertex_count());
  const std::span<const Vec3> normals = relit.transfer().view.scene.receiver_normals;
  const std::span<const Vec3> positions = relit.transfer().positions;
  const MetallicRoughness lacquer{{0.6, 0.3, 0.2}, 0, roughness};
  double largest = 0, scale = 0;
  lit = 0;
  const auto compare = [&](Vec3 p, Vec3 n, const auto& whole_of, const auto& specular_of,
                           const EnvironmentLighting::DiffuseLayerSums& sums) {
    const MetallicRoughnessToward toward(lacquer, n, normalize(eye - p));
    const Rgb whole = whole_of(toward);
    const Rgb split = specular_of(toward) + toward.diffuse_of_sums(sums.e, sums.a, sums.b);
    if (max_component(whole) > 0) ++lit;
    scale = std::max(scale, max_component(whole));
    largest = std::max({largest, std::abs(whole.r - split.r), std::abs(whole.g - split.g),
                        std::abs(whole.b - split.b)});
  };
  for (std::size_t r = 0; r < relit.transfer().vertex_count; ++r) {
    compare(
        positions[r], normals[r], [&](const auto& t) { return env.reflected(r, t); },
        [&](const auto& t) { return env.reflected(r, [&](Vec3 l) { return t.specular(l); }); },
        env.diffuse_layer(r, normals[r], roughness));
  }
  for (std::size_t q = 0; q < placed.vertex_count(); ++q) {
    compare(
        placed.positions[q], placed.normals[q],
        [&](const auto& t) { return env.reflected_object(q, placed, t); },
        [&](const auto& t) {
          return env.reflected_object(q, placed, [&](Vec3 l) { return t.specular(l); });
        },
        env.object_diffuse_layer(q, placed, placed.normals[q], roughness));
  }
  return scale > 0 ? largest / scale : 1.0;
}

TEST(GlossyView, KeptDiffuseSumsEqualTheWholeBrdfTo1e9AfterTheSunTheRoughnessAndTheBoxChange) {
  const testing::TempDir dir;
  RelitScene relit(testing::write_precomputed(dir, "showroom", lacquered_showroom()), std::nullopt);
  const Vec3 eye{2.5, 1.8, -2.2};
  int lit = 0;
  EXPECT_LT(largest_difference(relit, eye, 0.3, lit), 1e-9);  // made
  EXPECT_GT(lit, 100);
  EXPECT_LT(largest_difference(relit, eye + Vec3{0.3, 0, 0}, 0.3, lit), 1e-9);  // kept
  LightingState state = relit.state();
  apply_lighting_state(state, relit.scene(), nlohmann::json::parse(R"({
    "environment": {"type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
                    "sun": {"azimuth_deg": 120, "altitude_deg": 25}, "sun_illuminance": 60000}
  })"),
                       "test", dir.path());
  relit.apply(state);
  EXPECT_LT(largest_difference(relit, eye, 0.3, lit), 1e-9);  // the sun turned
  EXPECT_LT(largest_difference(relit, eye, 0.6, lit), 1e-9);  // another roughness
  apply_lighting_state(state, relit.scene(), nlohmann::json::parse(R"({
    "objects": {"box": {"translate": [0.7, 0, -0.4], "rotate_deg": 30}}
  })"),
                       "test", dir.path());
  relit.apply(state);
  EXPECT_LT(largest_difference(relit, eye, 0.6, lit), 1e-9);  // the box moved and turned
  EXPECT_GT(lit, 100);
}

}  // namespace
}  // namespace relight
