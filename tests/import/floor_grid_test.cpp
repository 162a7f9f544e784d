// Calculation grids on floors (import/floor_grid.h): the lattice is centred, every point keeps the
// border from the outline, and an edge two floor triangles share is not part of the outline.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "import/floor_grid.h"

namespace relight {
namespace {

std::vector<std::array<Vec3, 3>> rectangle(double x0, double z0, double x1, double z1) {
  return {{Vec3{x0, 0, z0}, Vec3{x1, 0, z0}, Vec3{x1, 0, z1}},
          {Vec3{x0, 0, z0}, Vec3{x1, 0, z1}, Vec3{x0, 0, z1}}};
}

TEST(FloorGrid, ARoomOf4By3MetresHas96PointsAtAQuarterMetreKeepingHalfAMetreFree) {
  const auto floor = rectangle(0, 0, 4, 3);
  const std::vector<Vec3> points = floor_grid(floor, 0.8, 0.25, 0.5);
  // Lattice centred on 4 × 3 m: x = 0.125 + 0.25 i, z = 0.125 + 0.25 j; of those, 12 × 8 lie
  // 0.5 m or more inside the walls.
  ASSERT_EQ(points.size(), 96u);
  for (const Vec3& p : points) {
    EXPECT_DOUBLE_EQ(p.y, 0.8);
    EXPECT_GE(std::min({p.x, 4 - p.x, p.z, 3 - p.z}), 0.5);
  }
  EXPECT_DOUBLE_EQ(points.front().x, 0.625);
  EXPECT_DOUBLE_EQ(points.front().z, 0.625);
}

TEST(FloorGrid, AnLShapedRoomKeepsPointsAlongTheEdgeItsTwoPartsShare) {
  auto floor = rectangle(0, 0, 4, 3);
  const auto wing = rectangle(4, 0, 6, 2);
  floor.insert(floor.end(), wing.begin(), wing.end());
  const std::vector<Vec3> points = floor_grid(floor, 0.8, 0.25, 0.5);
  const auto has = [&](double x, double z) {
    return std::any_of(points.begin(), points.end(), [&](const Vec3& p) {
      return std::abs(p.x - x) < 1e-9 && std::abs(p.z - z) < 1e-9;
    });
  };
  EXPECT_TRUE(has(3.875, 1.125));   // beside the shared edge x = 4, in the rectangle
  EXPECT_TRUE(has(4.125, 1.125));   // and in the wing
  EXPECT_FALSE(has(4.125, 1.625));  // 0.375 m from the wing's wall z = 2
  EXPECT_FALSE(has(3.875, 2.625));  // 0.125 m from the rectangle's wall x = 4 above the wing
}

TEST(FloorGrid, ARoomNarrowerThanTwoBordersHasNoPoints) {
  EXPECT_TRUE(floor_grid(rectangle(0, 0, 0.9, 5), 0.8, 0.25, 0.5).empty());
  EXPECT_TRUE(floor_grid({}, 0.8, 0.25, 0.5).empty());
}

}  // namespace
}  // namespace relight
