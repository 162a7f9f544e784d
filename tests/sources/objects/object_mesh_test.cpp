// The movable objects' placement (sources/objects/object_mesh.h).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "sources/objects/object_mesh.h"
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
  // Its box turned with it: 1 × 1 × 2 about (2.5, 0.5, 0.5).
  EXPECT_NEAR(length(placed.boxes[0].min - Vec3{2, 0, -0.5}), 0, 1e-9);
  EXPECT_NEAR(length(placed.boxes[0].max - Vec3{3, 1, 1.5}), 0, 1e-9);
  p.visible = false;
  const PlacedObjects hidden = place_objects(std::span(&mesh, 1), std::span(&p, 1));
  EXPECT_TRUE(hidden.triangles.empty());
  EXPECT_EQ(hidden.bounds[0].radius, 0);
  EXPECT_EQ(hidden.vertex_count(), mesh.positions.size());
}

TEST(ObjectMesh, EveryRayThatMeetsAnObjectMeetsItsBoxAndMostThatMissTheBoxAreToldSo) {
  // A table-like object (a top on one leg) and rays from points around and inside its box (a
  // floor point under the top), along 4,096 directions each: a ray the object's tracer finds
  // blocked always meets the box; rays the box turns away are most of those that miss it.
  const Scene scene = scene_from_json({{"materials", {{"m", {{"albedo", {0.5, 0.5, 0.5}}}}}},
                                       {"objects",
                                        {{{"name", "table"},
                                          {"geometry",
                                           {box({-0.6, 0.7, -0.4}, {0.6, 0.75, 0.4}, "m"),
                                            box({-0.05, 0, -0.05}, {0.05, 0.7, 0.05}, "m")}}}}}},
                                      "o.json");
  const ObjectMesh mesh = prepare_object(scene, scene.objects[0]);
  MovablePlacement p;
  p.rotate_deg = 30;
  const PlacedObjects placed = place_objects(std::span(&mesh, 1), std::span(&p, 1));
  std::vector<Vec3> directions;
  for (int i = 0; i < 4096; ++i) {
    // A spherical Fibonacci lattice.
    const double z = 1 - (2 * i + 1) / 4096.0, r = std::sqrt(1 - z * z), phi = 2.399963 * i;
    directions.push_back({r * std::cos(phi), z, r * std::sin(phi)});
  }
  std::size_t blocked_total = 0, missed_box = 0;
  for (const Vec3 origin :
       {Vec3{0.3, 0.001, 0.2}, Vec3{1.2, 0.3, 0.1}, Vec3{0.2, 1.5, -0.3}, Vec3{-0.9, 0.72, 0.8}}) {
    std::vector<std::uint8_t> blocked(directions.size());
    placed.own[0].occluded_from(origin, directions, blocked);
    for (std::size_t i = 0; i < directions.size(); ++i) {
      const bool meets = ray_meets_box(origin, directions[i], placed.boxes[0], 1e-4);
      if (blocked[i] != 0) {
        ASSERT_TRUE(meets) << i;
        ++blocked_total;
      }
      if (!meets) ++missed_box;
    }
  }
  std::printf("%zu rays blocked, %zu of 16,384 turned away by the box\n", blocked_total,
              missed_box);
  EXPECT_GT(blocked_total, 500u);
  // From inside the box none is turned away; from the three outside, most.
  EXPECT_GT(missed_box, 3 * 4096 / 2);
  // Along an axis: the slabs of the other two.
  const Bounds unit{{0, 0, 0}, {1, 1, 1}};
  EXPECT_TRUE(ray_meets_box({0.5, 0.5, -1}, {0, 0, 1}, unit, 0));
  EXPECT_FALSE(ray_meets_box({0.5, 1.5, -1}, {0, 0, 1}, unit, 0));
  EXPECT_FALSE(ray_meets_box({0.5, 0.5, -1}, {0, 0, -1}, unit, 0));
  EXPECT_TRUE(ray_meets_box({0.5, 1.00005, -1}, {0, 0, 1}, unit, 1e-4));
}

}  // namespace
}  // namespace relight
