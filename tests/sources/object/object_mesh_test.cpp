// The movable objects' placement (sources/object/object_mesh.h).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "sources/object/object_mesh.h"
#include "support/scene_json.h"

namespace relight {
namespace {

using nlohmann::json;
using testing::box;

TEST(ObjectMesh, PlacementTurnsAboutThePivotThenMovesAndHidingRemovesTheTriangles) {
  const Scene scene = scene_from_json(
      {{"materials", {{"m", {{"albedo", {0.5, 0.5, 0.5}}}}}},
       {"objects", {{{"name", "box"}, {"geometry", {box({1, 0, 1}, {3, 1, 2}, "m")}}}}}},
      "o.json");
  const ObjectMesh mesh = prepare_object(scene, scene.objects[0]);
  EXPECT_NEAR(length(mesh.pivot - Vec3{2, 0.5, 1.5}), 0, 1e-12);
  MovablePlacement p;
  p.translate = {0.5, 0, -1};
  p.rotate_deg = 90;
  const PlacedObjects placed = place_objects(std::span(&mesh, 1), std::span(&p, 1));
  // Turned 90° counter-clockwise seen from above (+x goes to −z), then moved.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 d = mesh.positions[v] - mesh.pivot;
    const Vec3 expected = mesh.pivot + Vec3{d.z, d.y, -d.x} + p.translate;
    EXPECT_NEAR(length(placed.positions[v] - expected), 0, 1e-9);
  }
  EXPECT_NEAR(length(placed.bounds[0].centre - Vec3{2.5, 0.5, 0.5}), 0, 1e-9);
  EXPECT_NEAR(placed.bounds[0].radius, 0.5 * std::sqrt(4 + 1 + 1), 1e-9);
  p.visible = false;
  const PlacedObjects hidden = place_objects(std::span(&mesh, 1), std::span(&p, 1));
  EXPECT_TRUE(hidden.triangles.empty());
  EXPECT_EQ(hidden.bounds[0].radius, 0);
  EXPECT_EQ(hidden.vertex_count(), mesh.positions.size());
}

}  // namespace
}  // namespace relight
