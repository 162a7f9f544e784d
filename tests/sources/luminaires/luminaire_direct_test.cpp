// The luminaire's direct factor in its two parts (sources/luminaires/luminaire_direct.h): the
// opening points one tracer leaves visible, then only those traced against another, give
// exactly what direct_factor gives with both tracers together — the split the movable objects
// keep per receiver (sources/objects/object_lighting.h).
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "sources/luminaires/luminaire_direct.h"
#include "trace/ray_tracer.h"

namespace relight {
namespace {

// A horizontal square of half-width h at height y, centred at (cx, cz), facing down.
RayTracer square(double cx, double cz, double y, double h) {
  const std::vector<Vec3> p{
      {cx - h, y, cz - h}, {cx + h, y, cz - h}, {cx + h, y, cz + h}, {cx - h, y, cz + h}};
  return RayTracer(p, {{0, 2, 1}, {0, 3, 2}}, {0, 1});
}

TEST(LuminaireDirect, TheRoomsVisiblePointsTracedAgainstTheObjectsGiveTheFactorOfBoth) {
  const RayTracer room = square(-0.35, 0, 1.5, 0.3);    // hides part of the opening's left
  const RayTracer objects = square(0.35, 0, 1.2, 0.3);  // and the object part of its right
  const Vec3 luminaire{0, 2.5, 0};
  std::vector<Vec3> opening;  // an 8 × 8 grid over 0.6 × 0.6 m
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j)
      opening.push_back({-0.3 + 0.6 * (i + 0.5) / 8, 0, -0.3 + 0.6 * (j + 0.5) / 8});
  }
  const Vec3 n{0, 1, 0};
  int penumbrae = 0;
  for (int s = 0; s <= 20; ++s) {
    const Vec3 p{-1.5 + 0.15 * s, 0, 0.2};
    std::uint64_t rays = 0;
    const double both =
        direct_factor(Occluders(room, &objects), p, n, luminaire, opening, rays).factor;
    const OpeningMask seen_by_room =
        visible_opening_points(room, p, n, luminaire, opening, all_opening_points(64), rays);
    const OpeningMask seen =
        visible_opening_points(objects, p, n, luminaire, opening, seen_by_room, rays);
    const double split = opening_point_count(seen) / 64.0 * direct_geometry(p, n, luminaire);
    EXPECT_EQ(both, split) << "at x = " << p.x;
    const Vec3 d = p - luminaire;
    EXPECT_NEAR(direct_geometry(p, n, luminaire), -d.y / length(d) / dot(d, d), 1e-15);
    if (opening_point_count(seen) > 0 && opening_point_count(seen) < 64) ++penumbrae;
  }
  EXPECT_GE(penumbrae, 4);  // points half shadowed, by the room, the object or both
  EXPECT_EQ(direct_geometry({0, 0, 0}, {0, -1, 0}, luminaire), 0);  // facing away
  std::uint64_t rays = 0;
  EXPECT_THROW(visible_opening_points(room, {0, 0, 0}, n, luminaire, std::vector<Vec3>(257),
                                      all_opening_points(256), rays),
               std::invalid_argument);
}

}  // namespace
}  // namespace relight
