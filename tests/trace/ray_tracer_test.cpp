// Embree wrapper: hits, misses, barycentrics, occlusion, ids, portals kept apart.
#include <thread>

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
