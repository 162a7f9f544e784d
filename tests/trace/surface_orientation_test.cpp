// The orientation check (trace/surface_orientation.h): a room shell turned inside out is found
// and turned whole, furniture turned inside out too; a correct room, window glass and an open
// floor seen from behind are left alone.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "scene/primitives.h"
#include "trace/surface_orientation.h"

namespace relight {
namespace {

constexpr std::uint32_t kWall = 0, kGlass = 1;
const std::vector<bool> kGlassMaterials{false, true};

TriangleSoup room(Facing facing) {
  return make_box({0, 0, 0}, {4, 3, 5}, facing, kWall);
}

bool all_turned(const SurfaceOrientation& o, std::uint32_t first, std::uint32_t count) {
  for (std::uint32_t t = first; t < first + count; ++t)
    if (std::find(o.turned.begin(), o.turned.end(), t) == o.turned.end()) return false;
  return true;
}

TEST(SurfaceOrientation, ARoomTurnedInsideOutIsTurnedWholeAndItsFurnitureLeftAlone) {
  TriangleSoup soup = room(Facing::kOutward);
  const auto shell = static_cast<std::uint32_t>(soup.triangles.size());
  soup.append(make_box({1, 0, 1}, {2, 0.75, 2}, Facing::kOutward, kWall));  // a table
  soup.append(make_quad({0.01, 1, 1}, {0, 0, 2}, {0, 1.5, 0}, kGlass));     // a window's glass
  const AirSeed luminaire{{2, 2.8, 2.5}};
  const SurfaceOrientation o = find_turned_surfaces(soup, kGlassMaterials, {&luminaire, 1});
  EXPECT_EQ(o.turned.size(), shell);
  EXPECT_TRUE(all_turned(o, 0, shell));
  EXPECT_EQ(o.checked, soup.triangles.size() - 2);  // the glass is not looked at
  EXPECT_FALSE(o.lattice_seeds);

  turn_triangles(soup, o.turned);
  const SurfaceOrientation again = find_turned_surfaces(soup, kGlassMaterials, {&luminaire, 1});
  EXPECT_TRUE(again.turned.empty());
  EXPECT_EQ(again.open_back_facing, 0u);
}

TEST(SurfaceOrientation, FurnitureTurnedInsideOutIsTurnedInACorrectRoom) {
  TriangleSoup soup = room(Facing::kInward);
  const auto shell = static_cast<std::uint32_t>(soup.triangles.size());
  soup.append(make_box({1, 0, 1}, {2, 0.75, 2}, Facing::kInward, kWall));
  const auto table = static_cast<std::uint32_t>(soup.triangles.size()) - shell;
  const AirSeed sensor{{3, 0.8, 4}, {0, 1, 0}};
  const SurfaceOrientation o = find_turned_surfaces(soup, kGlassMaterials, {&sensor, 1});
  // The table's underside stands on the floor: the flood reaches it only through the gap of
  // zero height, so it may stay unreached; every other face of it is turned.
  EXPECT_GE(o.turned.size(), table - 2);
  EXPECT_LE(o.turned.size(), table);
  for (const std::uint32_t t : o.turned) EXPECT_GE(t, shell);
}

TEST(SurfaceOrientation, AnOpenFloorSeenFromBehindIsReportedNotTurned) {
  const TriangleSoup soup = make_quad({0, 0, 0}, {4, 0, 0}, {0, 0, 4}, kWall);  // faces down
  const AirSeed luminaire{{2, 2, 2}};
  const SurfaceOrientation o = find_turned_surfaces(soup, kGlassMaterials, {&luminaire, 1});
  EXPECT_TRUE(o.turned.empty());
  EXPECT_EQ(o.open_back_facing, 2u);
  EXPECT_NE(orientation_warning(o).find("seen only from behind"), std::string::npos);
}

TEST(SurfaceOrientation, AModelWithoutSeedsIsSeededInsideItsRoomsNotInsideItsWalls) {
  TriangleSoup soup = room(Facing::kOutward);
  const auto shell = static_cast<std::uint32_t>(soup.triangles.size());
  // A solid wall 0.2 m thick standing in the room, correctly facing out: too thin to be a room.
  soup.append(make_box({0.5, 0, 2.4}, {3.5, 3, 2.6}, Facing::kOutward, kWall));
  const SurfaceOrientation o = find_turned_surfaces(soup, kGlassMaterials, {});
  EXPECT_TRUE(o.lattice_seeds);
  EXPECT_EQ(o.turned.size(), shell);
  EXPECT_TRUE(all_turned(o, 0, shell));
  EXPECT_NE(orientation_warning(o).find("turned 12 of 24 triangles"), std::string::npos);
}

TEST(SurfaceOrientation, TurningReversesTheWindingOnly) {
  TriangleSoup soup = make_quad({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, kWall);
  const TriangleSoup before = soup;
  const std::vector<std::uint32_t> first{0};
  turn_triangles(soup, first);
  EXPECT_EQ(soup.triangles[0][0], before.triangles[0][0]);
  EXPECT_EQ(soup.triangles[0][1], before.triangles[0][2]);
  EXPECT_EQ(soup.triangles[0][2], before.triangles[0][1]);
  EXPECT_EQ(soup.triangles[1], before.triangles[1]);
  EXPECT_EQ(soup.positions.size(), before.positions.size());
}

}  // namespace
}  // namespace relight
