// The texels a convex polygon covers, seen from a cubemap's centre (math/cubemap_polygon.h):
// conservative against dense sampling of random polygons, tight to one texel, exact on a face.
#include "math/cubemap_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

#include "math/cubemap.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "math/test_util.h"

namespace relight {
namespace {

std::vector<std::uint32_t> texels_of(int n, const std::vector<Vec3>& polygon, Vec3 front) {
  CubemapPolygonScratch scratch;
  std::vector<std::uint32_t> texels;
  cubemap_polygon_texels(n, polygon, front, scratch, texels);
  return texels;
}

// A random convex polygon (a regular m-gon, m = 3…8, stretched) at 0.05–3 m, 0.01–4 m across,
// turned at random.
std::vector<Vec3> random_polygon(Pcg32& rng) {
  const int m = 3 + static_cast<int>(rng.next_u32() % 6);
  const Vec3 centre = test::random_direction(rng) * (0.05 + 3 * rng.next_double());
  const Frame frame = frame_from_normal(test::random_direction(rng));
  const double size = 0.01 + 4 * rng.next_double(), stretch = 0.2 + rng.next_double();
  const double turn = 2 * kPi * rng.next_double();
  std::vector<Vec3> polygon;
  for (int k = 0; k < m; ++k) {
    const double a = turn + 2 * kPi * k / m;
    polygon.push_back(centre + frame.t * (size * std::cos(a)) +
                      frame.b * (size * stretch * std::sin(a)));
  }
  return polygon;
}

// Whether the ray from the centre along d meets the convex polygon.
bool through(const std::vector<Vec3>& polygon, Vec3 d) {
  const Vec3 normal = cross(polygon[1] - polygon[0], polygon[2] - polygon[0]);
  const double along = dot(normal, d);
  if (along == 0) return false;
  const double t = dot(normal, polygon[0]) / along;
  if (!(t > 0)) return false;
  const Vec3 x = d * t;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Vec3 a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    if (dot(cross(b - a, x - a), normal) < 0) return false;
  }
  return true;
}

TEST(CubemapPolygon, EveryDirectionThroughRandomPolygonsInAListedTexelAndNoneFartherThanOne) {
  const int n = 32;
  Pcg32 rng(11, 3);
  int listed_total = 0, hit_total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Vec3> polygon = random_polygon(rng);
    const Vec3 front = test::random_direction(rng);
    const std::vector<std::uint32_t> texels = texels_of(n, polygon, front);
    const std::set<std::uint32_t> listed(texels.begin(), texels.end());
    ASSERT_EQ(listed.size(), texels.size()) << "trial " << trial << ": a texel listed twice";
    // The texels that a direction of an 8 × 8 grid in them sends through the polygon.
    std::set<std::uint32_t> hit;
    for (std::size_t t = 0; t < cubemap_texel_count(n); ++t) {
      const CubemapTexel c = cubemap_texel_from_index(n, t);
      for (int b = 0; b < 8; ++b) {
        for (int a = 0; a < 8; ++a) {
          const Vec3 d =
              cubemap_direction({c.face, (c.i + (a + 0.5) / 8) / n, (c.j + (b + 0.5) / 8) / n});
          if (dot(d, front) > 0 && through(polygon, d)) hit.insert(static_cast<std::uint32_t>(t));
        }
      }
    }
    for (const std::uint32_t t : hit) {
      ASSERT_TRUE(listed.count(t)) << "trial " << trial << ": texel " << t << " missed";
    }
    // Tight: each listed texel is a sampled one's neighbour on its face, or on the face's
    // border (where its neighbour lies on the next face).
    for (const std::uint32_t t : listed) {
      const CubemapTexel c = cubemap_texel_from_index(n, t);
      const bool border = c.i == 0 || c.j == 0 || c.i == n - 1 || c.j == n - 1;
      bool near = border;
      for (int dj = -1; dj <= 1 && !near; ++dj) {
        for (int di = -1; di <= 1 && !near; ++di) {
          const int i = c.i + di, j = c.j + dj;
          near = i >= 0 && j >= 0 && i < n && j < n &&
                 hit.count(static_cast<std::uint32_t>(cubemap_texel_index(n, {c.face, i, j})));
        }
      }
      EXPECT_TRUE(near) << "trial " << trial << ": texel " << t << " listed far from the polygon";
    }
    listed_total += static_cast<int>(listed.size());
    hit_total += static_cast<int>(hit.size());
  }
  // Over all trials the listed texels are few more than the sampled ones (the outline's).
  EXPECT_LT(listed_total, 1.3 * hit_total);
}

TEST(CubemapPolygon, ASquareOnTheFaceListsExactlyTheTexelsItOverlaps) {
  // On +Z (direction (u, −v, 1)) the square covering texels i = 4…9, j = 10…13 with a quarter
  // texel to spare on each side.
  const int n = 16;
  const auto u = [n](double x) { return 2 * x / n - 1; };
  const double u0 = u(4.25), u1 = u(9.75), v0 = u(10.25), v1 = u(13.75);
  const std::vector<Vec3> polygon = {{u0, -v0, 1}, {u1, -v0, 1}, {u1, -v1, 1}, {u0, -v1, 1}};
  std::vector<std::uint32_t> texels = texels_of(n, polygon, {0, 0, 1});
  std::sort(texels.begin(), texels.end());
  std::vector<std::uint32_t> expected;
  for (int j = 10; j <= 13; ++j) {
    for (int i = 4; i <= 9; ++i) {
      expected.push_back(static_cast<std::uint32_t>(cubemap_texel_index(n, {kPosZ, i, j})));
    }
  }
  EXPECT_EQ(texels, expected);
  // Scaled along the directions (the same cone) it covers the same texels.
  std::vector<Vec3> far = polygon;
  for (Vec3& p : far) p = p * 7.5;
  std::vector<std::uint32_t> again = texels_of(n, far, {0, 0, 1});
  std::sort(again.begin(), again.end());
  EXPECT_EQ(again, expected);
}

TEST(CubemapPolygon, APolygonBehindTheFrontPlaneListsNothing) {
  const std::vector<Vec3> polygon = {{-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2}};
  EXPECT_TRUE(texels_of(32, polygon, {0, 0, 1}).empty());
  EXPECT_FALSE(texels_of(32, polygon, {0, 0, -1}).empty());
  // Partly in front (d · (1, 0, −0.2) > 0 where x > −0.4): fewer texels.
  const std::vector<std::uint32_t> half = texels_of(32, polygon, normalize(Vec3{1, 0, -0.2}));
  EXPECT_FALSE(half.empty());
  EXPECT_LT(half.size(), texels_of(32, polygon, {0, 0, -1}).size());
}

}  // namespace
}  // namespace relight
