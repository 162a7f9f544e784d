// Embree wrapper: hits, misses, barycentrics, occlusion, ids, portals kept apart.
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "trace/ray_tracer.h"

namespace relight {
namespace {

TEST(RayTracer, HitsTheRightTriangleWithBarycentrics) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}};
  const RayTracer tracer(p, {{0, 1, 2}, {3, 4, 5}}, {17, 42});
  const RayHit near = tracer.intersect({{0.25, 0.5, -1}, {0, 0, 1}});
  ASSERT_TRUE(near.hit());
  EXPECT_EQ(near.triangle, 17u);
  EXPECT_NEAR(near.t, 1.0, 1e-6);
  EXPECT_NEAR(near.u, 0.25, 1e-6);
  EXPECT_NEAR(near.v, 0.5, 1e-6);
  const RayHit far = tracer.intersect({{0.25, 0.5, 1}, {0, 0, 1}});
  EXPECT_EQ(far.triangle, 42u);
  EXPECT_FALSE(tracer.intersect({{2, 2, -1}, {0, 0, 1}}).hit());
}

TEST(RayTracer, OcclusionRespectsTheSegment) {
  const std::vector<Vec3> p = {{-1, -1, 1}, {1, -1, 1}, {0, 1, 1}};
  const RayTracer tracer(p, {{0, 1, 2}}, {0});
  EXPECT_TRUE(tracer.occluded({{0, 0, 0}, {0, 0, 1}, 0, 2}));
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {0, 0, 1}, 0, 0.9}));
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {0, 0, -1}, 0, 10}));
}

TEST(RayTracer, EmptySetNeverHits) {
  const RayTracer tracer({}, {}, {});
  EXPECT_FALSE(tracer.intersect({{0, 0, 0}, {0, 0, 1}}).hit());
  EXPECT_FALSE(tracer.occluded({{0, 0, 0}, {0, 0, 1}, 0, 1e9}));
}

// The batch (Embree's ray stream) finds what single rays find: 200 rays (more than one stream
// of 64, and a remainder) from points inside a closed box of 12 triangles toward random
// directions, each hit the same triangle at the same t, u, v (1e-6; both are Embree's float
// tests), and a ray pointing away from a lone triangle misses in both.
TEST(RayTracer, ABatchOfRaysHitsWhatEachRayHitsAlone) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<Triangle> box = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                     {0, 1, 5}, {0, 5, 4}, {3, 6, 2}, {3, 7, 6},
                                     {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  const RayTracer tracer(p, box, sequential_ids(box.size()));
  std::vector<Ray> rays;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.37 * i, b = 0.11 * i + 0.3;
    rays.push_back({{0.2 + 0.003 * i, 0.5, 0.8 - 0.003 * i},
                    {std::cos(a) * std::sin(b), std::cos(b), std::sin(a) * std::sin(b)}});
  }
  std::vector<RayHit> hits(rays.size());
  tracer.intersect(rays, hits);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const RayHit alone = tracer.intersect(rays[i]);
    ASSERT_TRUE(alone.hit()) << i;
    EXPECT_EQ(hits[i].triangle, alone.triangle) << i;
    EXPECT_NEAR(hits[i].t, alone.t, 1e-6) << i;
    EXPECT_NEAR(hits[i].u, alone.u, 1e-6) << i;
    EXPECT_NEAR(hits[i].v, alone.v, 1e-6) << i;
  }
  const RayTracer lone(p, {{0, 1, 2}}, {5});
  std::vector<RayHit> away(1);
  lone.intersect(std::vector<Ray>{{{0.5, 0.5, 1}, {0, 0, 1}}}, away);
  EXPECT_FALSE(away[0].hit());
  EXPECT_THROW(lone.intersect(rays, away), std::invalid_argument);
}

// Packets from one point answer as single rays: 203 directions (25 packets of eight and a
// remainder of three) from a point above a unit square, about half of them blocked by it, each
// the same as occluded() alone; a size mismatch throws.
TEST(RayTracer, OneOriginsPacketsOfEightAnswerAsSingleRays) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  const RayTracer tracer(p, {{0, 1, 2}, {0, 2, 3}}, {0, 1});
  const Vec3 origin{0.3, 0.4, 0.6};
  std::vector<Vec3> directions;
  for (int i = 0; i < 203; ++i) {
    const double a = 0.37 * i, b = 0.0155 * i;
    directions.push_back({std::cos(a) * std::sin(b), -std::cos(b), std::sin(a) * std::sin(b)});
  }
  std::vector<std::uint8_t> blocked(directions.size(), 7);
  tracer.occluded_from(origin, directions, blocked);
  std::size_t count = 0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    EXPECT_EQ(blocked[i] != 0, tracer.occluded({origin, directions[i]})) << i;
    EXPECT_LE(blocked[i], 1) << i;
    count += blocked[i];
  }
  EXPECT_GT(count, 50u);
  EXPECT_LT(count, 153u);
  std::vector<std::uint8_t> short_answers(3);
  EXPECT_THROW(tracer.occluded_from(origin, directions, short_answers), std::invalid_argument);
}

TEST(RayTracer, IsSafeFromManyThreads) {
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  std::vector<std::uint32_t> ids;
  for (int i = 0; i < 100; ++i) {
    const auto base = static_cast<std::uint32_t>(p.size());
    p.push_back({-1, -1, double(i)});
    p.push_back({1, -1, double(i)});
    p.push_back({0, 1, double(i)});
    t.push_back({base, base + 1, base + 2});
    ids.push_back(i);
  }
  const RayTracer tracer(p, t, ids);
  std::vector<std::uint32_t> hits(1000);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      for (int i = k; i < 1000; i += 4) {
        hits[i] = tracer.intersect({{0, 0, (i % 100) - 0.5}, {0, 0, 1}}).triangle;
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(hits[i], static_cast<std::uint32_t>(i % 100));
}

}  // namespace
}  // namespace relight
