// An environment clustered on the direction tree (light/environment_clusters.h): the first
// moments of every node sum its children's; over the leaves above a horizontal plane, n · M
// gives the plane's illuminance — π L for a uniform environment, the dome's and the sun's
// horizontal illuminance for a CIE sky with a sun, a small source's E·cos for a map — to
// within the leaves' quadrature at the horizon; a sun's light lands in the leaves about its
// direction.
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "light/environment.h"
#include "light/environment_clusters.h"
#include "math/direction_tree.h"
#include "math/equirect.h"

namespace relight {
namespace {

const DirectionTree& tree() {
  static const DirectionTree t = build_direction_tree(repulsed_directions(8192, 10));
  return t;
}

// Σ over the leaves above the plane of normal n of n · M.
Rgb plane_irradiance(const std::vector<RgbMoment>& m, Vec3 n) {
  const std::size_t count = tree().leaf_count();
  Rgb e{};
  for (std::size_t i = 0; i < count; ++i) {
    if (dot(tree().leaves[i], n) > 0) e += m[count + i].irradiance(n);
  }
  return e;
}

TEST(EnvironmentClusters, AUniformEnvironmentGivesAPlanePiLAndNodesSumTheirChildren) {
  const PointGrid leaves = leaf_grid(tree());
  const std::vector<RgbMoment> m =
      environment_moments(make_uniform_environment({1000, 500, 250}), tree(), leaves);
  ASSERT_EQ(m.size(), 2 * tree().leaf_count());
  for (const Vec3 n : {Vec3{0, 1, 0}, normalize(Vec3{1, -0.4, 0.3})}) {
    const Rgb e = plane_irradiance(m, n);
    EXPECT_NEAR(e.r, kPi * 1000, 0.002 * kPi * 1000);
    EXPECT_NEAR(e.b, kPi * 250, 0.002 * kPi * 250);
  }
  for (const std::size_t k : {std::size_t{1}, std::size_t{37}, std::size_t{4000}}) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(m[k].r[i], m[2 * k].r[i] + m[2 * k + 1].r[i], 1e-3) << k;
    }
  }
  EXPECT_NEAR(m[1].irradiance({0, 1, 0}).r, 0, 1.0);  // ∫ L ω dω = 0 over the sphere
}

TEST(EnvironmentClusters, ACieSkyWithASunGivesItsHorizontalIlluminance) {
  const Vec3 sun = normalize(Vec3{0.3, 0.7, 0.5});
  const Environment env =
      make_sky_environment(make_sky_from_horizontal_illuminance(12, sun, 15000, 0.2, 70000));
  const PointGrid leaves = leaf_grid(tree());
  const std::vector<RgbMoment> m = environment_moments(env, tree(), leaves);
  const double expected = env.sky.sky_horizontal_illuminance + env.sky.sun_horizontal_illuminance;
  const Rgb e = plane_irradiance(m, {0, 1, 0});
  std::printf("CIE sky 12 with a sun: %.1f lx against %.1f\n", e.g, expected);
  EXPECT_NEAR(e.g, expected, 0.003 * expected);
  // The sun's light is in the leaves about it: those within 2° hold 70000 · cos of it.
  const std::size_t count = tree().leaf_count();
  double near_sun = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (dot(tree().leaves[i], sun) > std::cos(2 * kPi / 180)) {
      near_sun += m[count + i].irradiance(sun).g;
    }
  }
  EXPECT_GT(near_sun, 70000 * 0.99);
  EXPECT_LT(near_sun, 70000 * 1.01 + 200);  // and a little sky
}

TEST(EnvironmentClusters, AMapsSmallSourceKeepsItsCosine) {
  auto map = std::make_shared<EquirectMap>();
  map->width = 1024;
  map->height = 512;
  map->texels.assign(1024 * 512, Rgb{});
  const int i0 = 300, j0 = 150;  // 52.7° from the zenith
  double omega = 0;
  for (int j = j0; j < j0 + 2; ++j) {
    for (int i = i0; i < i0 + 2; ++i) {
      map->texels[static_cast<std::size_t>(j) * 1024 + i] = Rgb{1e6, 1e6, 1e6};
      omega += equirect_row_solid_angle(1024, 512, j);
    }
  }
  const Environment env = make_map_environment(map, 40, 2);
  const Vec3 source =
      MapRotation(40).to_world(equirect_direction((i0 + 1.0) / 1024, (j0 + 1.0) / 512));
  const PointGrid leaves = leaf_grid(tree());
  const std::vector<RgbMoment> m = environment_moments(env, tree(), leaves);
  const double expected = 2e6 * omega * source.y;
  EXPECT_NEAR(plane_irradiance(m, {0, 1, 0}).r, expected, 0.002 * expected);
}

// The grid's parts kept from call to call (a sky moving frame to frame) give the same floats as
// parts placed afresh, and are placed again when the grid or the frame changes.
TEST(EnvironmentClusters, KeptGridPartsGiveTheMomentsOfAFreshGridAndFollowTheFrame) {
  const PointGrid leaves = leaf_grid(tree());
  EnvironmentGridParts kept;
  const auto same = [](const std::vector<RgbMoment>& a, const std::vector<RgbMoment>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 1; k < a.size(); ++k) {
      for (int i = 0; i < 3; ++i) {
        if (a[k].r[i] != b[k].r[i] || a[k].g[i] != b[k].g[i] || a[k].b[i] != b[k].b[i]) {
          return false;
        }
      }
    }
    return true;
  };
  for (const double frame : {0.0, 0.0, 25.0}) {
    for (const double azimuth : {0.2, 1.4}) {
      const Vec3 sun = normalize(Vec3{std::cos(azimuth), 0.6, std::sin(azimuth)});
      const Environment sky =
          make_sky_environment(make_sky_from_horizontal_illuminance(12, sun, 15000, 0.2, 70000));
      const std::vector<RgbMoment> fresh = environment_moments(sky, tree(), leaves, frame);
      EXPECT_TRUE(same(environment_moments(sky, tree(), leaves, frame, nullptr, &kept), fresh))
          << frame << " " << azimuth;
      EXPECT_EQ(kept.key.frame_rotate_deg, frame);
    }
  }
  // A map after the sky (as many texels as the sky's grid has parts; a map's texels are split
  // finer, so its grid is its own), unturned and turned: placed again each time.
  auto map = std::make_shared<EquirectMap>();
  map->width = kept.key.width;
  map->height = kept.key.height;
  for (int t = 0; t < map->width * map->height; ++t) {
    map->texels.push_back(Rgb{1.0 + t % 7, 2.0, 0.5 * (t % 3)});
  }
  for (const double turn : {0.0, 40.0}) {
    const Environment env = make_map_environment(map, turn, 2);
    EXPECT_TRUE(same(environment_moments(env, tree(), leaves, 25, nullptr, &kept),
                     environment_moments(env, tree(), leaves, 25)))
        << turn;
    EXPECT_TRUE(kept.key.map);
    EXPECT_EQ(kept.key.map_rotate_deg, turn);
  }
  EXPECT_EQ(kept.leaf.size(), static_cast<std::size_t>(kept.key.width) * kept.key.height *
                                  kept.key.parts * kept.key.parts);
}

}  // namespace
}  // namespace relight
