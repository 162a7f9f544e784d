// The portal's geometry and Yue et al. 2009's §6 shell-size check.
#include "sources/portals/portal_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

#include "scene/scene_loader.h"

namespace relight {
namespace {

Scene window_scene(double exterior_distance, double tower_z) {
  nlohmann::json doc = nlohmann::json::parse(R"({
    "materials": { "wall": { "albedo": [0.5, 0.5, 0.5] },
                   "glass": { "albedo": [0, 0, 0], "portal": true } },
    "geometry": [ { "type": "quad", "corner": [1, 1, 5], "u": [0, 1.5, 0], "v": [2, 0, 0],
                    "material": "glass" },
                  { "type": "quad", "corner": [0, 0, 0], "u": [0, 0, 5], "v": [4, 0, 0],
                    "material": "wall" } ],
    "portals": [ { "name": "south", "material": "glass",
                   "environment": { "type": "uniform", "luminance": 1000 } } ]
  })");
  if (exterior_distance > 0) doc["portals"][0]["exterior_distance"] = exterior_distance;
  if (tower_z > 0) {
    doc["exterior"] = {{{"name", "tower"},
                        {"type", "box"},
                        {"min", {-5, 0, tower_z}},
                        {"max", {10, 10, tower_z + 2}},
                        {"material", "wall"}}};
  }
  return scene_from_json(doc, "w.json");
}

TEST(PortalGeometry, AreaCentreNormalAndDiameterOfAWindow) {
  const Scene scene = window_scene(0, 0);
  const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
  const std::vector<PortalGeometry> g = portal_geometry(scene, mesh);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_NEAR(g[0].area, 3.0, 1e-9);
  EXPECT_NEAR(length(g[0].centre - Vec3{2, 1.75, 5}), 0, 1e-9);
  EXPECT_NEAR(std::abs(g[0].normal.z), 1, 1e-12);
  EXPECT_NEAR(g[0].diameter, 2.5, 1e-9);  // the diagonal of 2 × 1.5 m
  EXPECT_GT(g[0].triangles.size(), 2u);   // subdivided to max_edge
}

TEST(PortalGeometry, ShellCheckFollowsLOver2R) {
  EXPECT_NEAR(shell_direction_error(0.5, 3), 0.5 / 6, 1e-15);
  // Only sky: never flagged.
  {
    const Scene scene = window_scene(0, 0);
    const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
    EXPECT_TRUE(shell_size_warnings(scene, portal_geometry(scene, mesh)).empty());
  }
  // A 2.5 m window with the exterior 3 m away: 2.5/6 rad = 23.9° > 5°; the largest portal is
  // 2·3·5° = 0.52 m.
  {
    const Scene scene = window_scene(3, 0);
    const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
    const auto w = shell_size_warnings(scene, portal_geometry(scene, mesh));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("l/(2r) = 23.9 deg exceeds shell_tolerance_deg 5.0"), std::string::npos);
    EXPECT_NE(w[0].find("at most 0.52 m"), std::string::npos);
  }
  // The nearest exterior triangle: a tower face 40 m south of the window: 2.5/80 rad = 1.8°.
  {
    const Scene scene = window_scene(0, 45);
    EXPECT_NEAR(nearest_exterior_distance({2, 1.75, 5}, scene.exterior), 40, 1e-9);
    const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
    EXPECT_TRUE(shell_size_warnings(scene, portal_geometry(scene, mesh)).empty());
  }
  {
    const Scene scene = window_scene(0, 8);  // 3 m away: flagged
    const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
    const auto w = shell_size_warnings(scene, portal_geometry(scene, mesh));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("nearest exterior geometry"), std::string::npos);
  }
}

TEST(PortalGeometry, GlassOnlyVerticesAreMarked) {
  const Scene scene = window_scene(0, 0);
  const PreparedMesh mesh = prepare_mesh(scene.geometry, {0.25, 30});
  const std::vector<std::uint8_t> glass = portal_vertices(mesh, scene.materials);
  std::size_t marked = 0;
  for (std::size_t v = 0; v < glass.size(); ++v) {
    if (glass[v]) {
      ++marked;
      EXPECT_NEAR(mesh.positions[v].z, 5, 1e-12);
    }
  }
  EXPECT_GT(marked, 4u);
}

}  // namespace
}  // namespace relight
