// Proxies for vertices far from a movable object (sources/objects/receiver_proxies.h): stencils
// that stay on their own surface and group, weights that sum to one, and a smooth field
// interpolated from the proxies alone.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "sources/objects/receiver_proxies.h"

namespace relight {
namespace {

// A grid of n × n points over [0, 1]² in the plane y = height, normal ±y.
void add_grid(std::vector<Vec3>& points, std::vector<Vec3>& normals,
              std::vector<std::uint32_t>& group, int n, double height, double normal_y,
              std::uint32_t g) {
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      points.push_back({i / (n - 1.0), height, j / (n - 1.0)});
      normals.push_back({0, normal_y, 0});
      group.push_back(g);
    }
  }
}

TEST(ReceiverProxies, StencilsStayOnTheirSurfaceAndGroupAndTheirWeightsSumToOne) {
  std::vector<Vec3> points, normals;
  std::vector<std::uint32_t> group;
  add_grid(points, normals, group, 21, 0, 1, 0);      // a floor
  add_grid(points, normals, group, 21, 0.01, -1, 0);  // a plate's underside 1 cm above it
  add_grid(points, normals, group, 21, 0.02, 1, 1);   // another object's top
  const ReceiverProxies p = build_receiver_proxies(points, normals, group, 0.2);
  EXPECT_LT(p.proxies.size(), points.size() / 8);
  for (std::size_t v = 0; v < points.size(); ++v) {
    float total = 0;
    ASSERT_GT(p.first[v + 1], p.first[v]);
    for (std::uint32_t i = p.first[v]; i < p.first[v + 1]; ++i) {
      const std::uint32_t proxy = p.proxies[p.stencil[i]];
      EXPECT_EQ(group[proxy], group[v]);
      EXPECT_GT(dot(normals[proxy], normals[v]), 0.9);
      EXPECT_LT(length(points[proxy] - points[v]), 0.2 * std::sqrt(3.0) + 1e-9);
      total += p.weights[i];
    }
    EXPECT_NEAR(total, 1, 1e-6);
    if (p.proxy_of[v] >= 0) {  // a proxy's stencil is itself
      ASSERT_EQ(p.first[v + 1] - p.first[v], 1u);
      EXPECT_EQ(p.proxies[p.stencil[p.first[v]]], v);
    }
  }
}

// A field that varies like an object's contribution 2 m away, f = 1 / (4 + |x − c|²), spread from
// its values at the proxies, within 2 % everywhere on the floor.
TEST(ReceiverProxies, AFieldSmoothOnTheSpacingIsInterpolatedWithinTwoPercent) {
  std::vector<Vec3> points, normals;
  std::vector<std::uint32_t> group;
  add_grid(points, normals, group, 41, 0, 1, 0);
  const ReceiverProxies p = build_receiver_proxies(points, normals, group, 0.1);
  const auto f = [](Vec3 x) {
    const Vec3 d = x - Vec3{0.5, 0, 0.5};
    return 1 / (4 + dot(d, d));
  };
  std::vector<float> values;
  for (const std::uint32_t v : p.proxies) {
    values.insert(values.end(), 3, static_cast<float>(f(points[v])));
  }
  std::vector<std::uint8_t> use(points.size(), 1);
  const std::vector<std::span<const std::uint8_t>> layers{use};
  std::vector<float> out(3 * points.size(), 0.0f);
  spread_from_proxies(p, layers, values, out);
  double worst = 0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    worst = std::max(worst, std::abs(out[3 * v] / f(points[v]) - 1));
  }
  std::printf("worst relative error of the spread field: %.5f\n", worst);
  EXPECT_LT(worst, 0.02);
}

TEST(ReceiverProxies, OnlyVerticesThatAreNotProxiesAndFarEnoughTakeProxyRows) {
  std::vector<Vec3> points, normals;
  std::vector<std::uint32_t> group;
  add_grid(points, normals, group, 11, 0, 1, 0);
  const ReceiverProxies p = build_receiver_proxies(points, normals, group, 0.25);
  const BoundingSphere sphere{{0, 0.5, 0}, 0.1};
  for (std::size_t v = 0; v < points.size(); ++v) {
    const double outside = length(points[v] - sphere.centre) - sphere.radius;
    EXPECT_EQ(takes_proxy_row(p, v, points[v], sphere, 2),
              p.proxy_of[v] < 0 && outside >= 2 * 0.25);
    EXPECT_FALSE(takes_proxy_row(p, v, points[v], BoundingSphere{}, 2));  // hidden
  }
}

}  // namespace
}  // namespace relight
