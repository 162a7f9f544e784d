// The compact sources of an environment (light/compact_sources.h): a sky's sun; a map's small
// bright spot found where it is painted, as a disc of its solid angle and energy, its texels
// left out of the moments (light/environment_clusters.h) so that the light is counted once; a
// large bright region, a uniform environment and a faint spot give none.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "light/compact_sources.h"
#include "light/environment.h"
#include "light/environment_clusters.h"
#include "math/direction_tree.h"
#include "math/equirect.h"

namespace relight {
namespace {

constexpr int kWidth = 1024, kHeight = 512;

// A map of `rest` cd/m² with the texels whose centres lie within radius_deg of `dir` sharing
// ∫L dω = `lux`; returns how many texels the spot has and their centroid (Σ Ω ω, normalised).
struct Spot {
  std::size_t texels = 0;
  Vec3 centroid;
};
Spot paint(EquirectMap& map, Vec3 dir, double radius_deg, double lux, double rest) {
  map = {kWidth, kHeight, {}};
  map.texels.assign(static_cast<std::size_t>(kWidth) * kHeight, Rgb{rest, rest, rest});
  const double cos_r = std::cos(radius_deg * kPi / 180);
  std::vector<std::size_t> in;
  double omega = 0;
  Vec3 centroid;
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const Vec3 d = equirect_texel_direction(kWidth, kHeight, i, j);
      if (dot(d, dir) >= cos_r) {
        in.push_back(static_cast<std::size_t>(j) * kWidth + i);
        omega += equirect_row_solid_angle(kWidth, kHeight, j);
        centroid += d * equirect_row_solid_angle(kWidth, kHeight, j);
      }
    }
  }
  for (const std::size_t t : in) map.texels[t] = Rgb{lux / omega, 0.5 * lux / omega, lux / omega};
  return {in.size(), normalize(centroid)};
}

double angle_deg(Vec3 a, Vec3 b) {
  return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) * 180 / kPi;
}

TEST(CompactSources, ASkysSunIsItsOnlySource) {
  const Vec3 sun = normalize(Vec3{0.3, 0.7, 0.5});
  const Environment env =
      make_sky_environment(make_sky_from_horizontal_illuminance(12, sun, 15000, 0.2, 70000));
  const CompactSources found = find_compact_sources(env);
  ASSERT_EQ(found.sources.size(), 1u);
  EXPECT_TRUE(found.sky_sun);
  EXPECT_TRUE(found.map_texels.empty());
  EXPECT_LT(angle_deg(found.sources[0].disc.direction, sun), 1e-9);
  EXPECT_DOUBLE_EQ(found.sources[0].illuminance.g, 70000);
  EXPECT_TRUE(find_compact_sources(make_uniform_environment({1000, 1000, 1000})).sources.empty());
}

TEST(CompactSources, AMapsHalfDegreeSpotIsFoundWhereItIsWithItsEnergy) {
  const Vec3 dir = normalize(Vec3{-0.8, 0.5, 0.33});
  auto map = std::make_shared<EquirectMap>();
  const Spot spot = paint(*map, dir, 0.5, 40000, 500);
  // Turned by 90°: the source turns with the map.
  const Environment env = make_map_environment(map, 90, 2);
  const CompactSources found = find_compact_sources(env);
  ASSERT_EQ(found.sources.size(), 1u);
  const CompactSource& s = found.sources[0];
  // Where the painted texels' centroid is (0.04° from `dir`: the texels' steps).
  const Vec3 turned = MapRotation(90).to_world(spot.centroid);
  EXPECT_LT(angle_deg(s.disc.direction, turned), 1e-6);
  EXPECT_NEAR(s.disc.angular_radius * 180 / kPi, 0.5, 0.05);
  // ∫L dω · scale, at normal incidence: a disc's π sin²r over its 2π(1 − cos r).
  const double to_normal = (1 + s.disc.cos_angular_radius) / 2;
  EXPECT_NEAR(s.illuminance.r, 2 * 40000 * to_normal, 1e-6 * 80000);
  EXPECT_NEAR(s.illuminance.g, 2 * 20000 * to_normal, 1e-6 * 40000);
  std::size_t masked = 0;
  for (const std::uint8_t m : found.map_texels) masked += m;
  EXPECT_EQ(masked, spot.texels);

  // The moments without the spot: they differ from the whole map's by the spot's ∫L ω dω alone.
  const DirectionTree tree = build_direction_tree(repulsed_directions(2048, 10));
  const PointGrid leaves = leaf_grid(tree);
  const std::vector<RgbMoment> all = environment_moments(env, tree, leaves);
  const std::vector<RgbMoment> rest = environment_moments(env, tree, leaves, 0, &found);
  for (const Vec3 n : {turned, Vec3{0, 1, 0}}) {
    const double e = all[1].irradiance(n).r - rest[1].irradiance(n).r;
    EXPECT_NEAR(e, 2 * 40000 * dot(n, turned), 0.002 * 80000);
  }
}

TEST(CompactSources, LargeOrFaintSpotsStayInTheCuts) {
  auto map = std::make_shared<EquirectMap>();
  // 10° across: wider than kCompactMaxRadiusDeg.
  paint(*map, normalize(Vec3{0.2, 0.9, -0.1}), 5, 400000, 100);
  CompactSources found = find_compact_sources(make_map_environment(map, 0, 1));
  EXPECT_TRUE(found.sources.empty());
  for (const std::uint8_t m : found.map_texels) ASSERT_EQ(m, 0);
  // Bright against its neighbours but below kCompactMinShare of the map's light.
  paint(*map, normalize(Vec3{0.2, 0.9, -0.1}), 0.5, 0.002 * 4 * kPi * 1000, 1000);
  found = find_compact_sources(make_map_environment(map, 0, 1));
  EXPECT_TRUE(found.sources.empty());
}

}  // namespace
}  // namespace relight
