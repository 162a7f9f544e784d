// The specular lobe summed over many lights in single precision (material/specular_lobe_sum.h)
// against MetallicRoughnessToward::specular in double, one light at a time: random lights of
// random moments (some channels negative, some lights below the surface) and lights about the
// mirror direction at 0.1–10 α, for roughness 0.01–1, dielectric and metal, eyes from the
// normal to 85°, on both paths (AVX2 where the processor has it, and the portable one), in
// groups that end mid-vector, with a weight, from a MomentLightBatch and one by one. Within 1e-5 +
// 6e-8/α of the largest channel of the sum (a float's rounding of a direction, ~6e-8 rad, moves a
// lobe of width α: 6.1e-4 at roughness 0.01, 3.4e-5 at 0.05, 1.1e-5 at 0.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "material/metallic_roughness.h"
#include "material/specular_lobe_sum.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace relight {
namespace {

struct Lights {
  std::array<std::vector<float>, 12> plane;
  void push(const std::array<float, 9>& m, Vec3 l) {
    for (std::size_t i = 0; i < 9; ++i) plane[i].push_back(m[i]);
    plane[9].push_back(static_cast<float>(l.x));
    plane[10].push_back(static_cast<float>(l.y));
    plane[11].push_back(static_cast<float>(l.z));
  }
  std::size_t size() const { return plane[0].size(); }
  MomentLightPlanes planes() const {
    MomentLightPlanes p;
    for (std::size_t i = 0; i < 12; ++i) p.plane[i] = plane[i].data();
    return p;
  }
  // Light k as stored: its direction and its irradiance at n, in double.
  Vec3 direction(std::size_t k) const { return {plane[9][k], plane[10][k], plane[11][k]}; }
  Rgb irradiance(std::size_t k, Vec3 n) const {
    const auto e = [&](std::size_t c) {
      return n.x * plane[3 * c][k] + n.y * plane[3 * c + 1][k] + n.z * plane[3 * c + 2][k];
    };
    return {e(0), e(1), e(2)};
  }
};

// Lights for normal n and eye v: random directions and moments, then directions about the
// mirror direction at angles of 0.1–10 α with moments along n.
Lights make_lights(Vec3 n, Vec3 v, double alpha, Pcg32& rng) {
  Lights lights;
  for (int i = 0; i < 300; ++i) {
    const Vec3 l = sample_uniform_sphere(rng.next_double(), rng.next_double());
    std::array<float, 9> m{};
    for (float& x : m) x = static_cast<float>(rng.next_double() * 2 - 0.6);
    lights.push(m, l);
  }
  const Vec3 mirror = n * (2 * dot(n, v)) - v;
  const Frame frame = frame_from_normal(mirror);
  for (int i = 0; i < 100; ++i) {
    const double angle = alpha * std::pow(10.0, rng.next_double() * 2 - 1);
    const double phi = 2 * kPi * rng.next_double();
    const Vec3 l = normalize(frame.to_world(
        {std::sin(angle) * std::cos(phi), std::sin(angle) * std::sin(phi), std::cos(angle)}));
    const std::array<float, 9> m{static_cast<float>(n.x),        static_cast<float>(n.y),
                                 static_cast<float>(n.z),        0.5f * static_cast<float>(n.x),
                                 0.5f * static_cast<float>(n.y), 0.5f * static_cast<float>(n.z),
                                 0.2f * static_cast<float>(n.x), 0.2f * static_cast<float>(n.y),
                                 0.2f * static_cast<float>(n.z)};
    lights.push(m, l);
  }
  return lights;
}

// Σ over lights [begin, end) in double, as the view summed them one at a time.
Rgb one_at_a_time(const MetallicRoughnessToward& brdf, const Lights& lights, Vec3 n,
                  std::size_t begin, std::size_t end) {
  Rgb sum;
  for (std::size_t k = begin; k < end; ++k) {
    const Rgb e = lights.irradiance(k, n);
    if (e.r > 0 || e.g > 0 || e.b > 0) sum += e * brdf.specular(lights.direction(k));
  }
  return sum;
}

double relative_difference(const Rgb& a, const Rgb& b) {
  const double scale = std::max(max_component(b), 1e-300);
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) / scale;
}

TEST(SpecularLobeSum, EqualsTheDoubleLobeOneLightAtATimeTo1e5Plus6e8OverAlphaOnBothPaths) {
  Pcg32 rng(7, 11);
  for (const double roughness : {0.01, 0.05, 0.3, 0.7, 1.0}) {
    for (const double metallic : {0.0, 1.0}) {
      for (const double view_deg : {0.0, 30.0, 60.0, 85.0}) {
        const Vec3 n = normalize(Vec3{0.3, 0.9, -0.2});
        const Frame frame = frame_from_normal(n);
        const double t = view_deg * kPi / 180;
        const Vec3 v = normalize(frame.to_world({std::sin(t), 0.3 * std::sin(t), std::cos(t)}));
        const MetallicRoughness m{{0.9, 0.6, 0.3}, metallic, roughness};
        const MetallicRoughnessToward brdf(m, n, v);
        // A float's rounding of a direction (~6e-8 rad) against the lobe's width α, plus the
        // sum's rounding (measured: 1.2e-4 at roughness 0.01, 1.6e-5 at 0.05, 5.4e-6 at 0.3).
        const double alpha = std::max(roughness * roughness, 1e-4);
        const double tolerance = 1e-5 + 6e-8 / alpha;
        const Lights lights = make_lights(n, v, alpha, rng);
        // Groups that end mid-vector, and one light alone.
        const std::size_t cut1 = 13, cut2 = lights.size() - 5;
        const Rgb expected = one_at_a_time(brdf, lights, n, 0, lights.size());
        ASSERT_GT(max_component(expected), 0);
        for (const auto path :
             {SpecularLobeSum::Path::kFastest, SpecularLobeSum::Path::kPortable}) {
          SpecularLobeSum sum(brdf, path);
          sum.add(lights.planes(), 0, cut1, 1);
          sum.add(lights.planes(), cut1, cut1 + 1, 1);
          sum.add(lights.planes(), cut1 + 1, cut2, 1);
          sum.add(lights.planes(), cut2, lights.size(), 1);
          EXPECT_LT(relative_difference(sum.total(), expected), tolerance)
              << "roughness " << roughness << " metallic " << metallic << " view " << view_deg;
          // A weight scales the sum.
          SpecularLobeSum weighted(brdf, path);
          weighted.add(lights.planes(), 0, lights.size(), 0.25f);
          EXPECT_LT(relative_difference(weighted.total(), expected * 0.25), tolerance);
        }
      }
    }
  }
}

TEST(SpecularLobeSum, BatchedAndOneByOneLightsEqualThePlanesAndAViewerBelowTheSurfaceSeesNothing) {
  Pcg32 rng(3, 5);
  const Vec3 n{0, 1, 0};
  const Vec3 v = normalize(Vec3{0.4, 0.8, 0.1});
  const MetallicRoughness m{{0.5, 0.5, 0.5}, 0, 0.3};
  const MetallicRoughnessToward brdf(m, n, v);
  const Lights lights = make_lights(n, v, 0.09, rng);
  MomentLightBatch batch;
  SpecularLobeSum batched(brdf);
  for (std::size_t k = 0; k < lights.size(); ++k) {
    std::array<float, 9> moment{};
    for (std::size_t i = 0; i < 9; ++i) moment[i] = lights.plane[i][k];
    batch.push(moment.data(), lights.direction(k), 2.0f);  // the weight scales the moments
    if (batch.full()) {
      batched.add(batch, 0.5f);
      batch.clear();
    }
  }
  batched.add(batch, 0.5f);
  const Rgb expected = one_at_a_time(brdf, lights, n, 0, lights.size());
  EXPECT_LT(relative_difference(batched.total(), expected), 2e-5);
  // One at a time, kept until a batch is full (and the rest by total()).
  SpecularLobeSum one_by_one(brdf);
  for (std::size_t k = 0; k < lights.size(); ++k) {
    std::array<float, 9> moment{};
    for (std::size_t i = 0; i < 9; ++i) moment[i] = lights.plane[i][k];
    one_by_one.add_one(moment, lights.direction(k));
  }
  EXPECT_LT(relative_difference(one_by_one.total(), expected), 2e-5);

  const MetallicRoughnessToward below(m, n, normalize(Vec3{0.4, -0.2, 0.1}));
  SpecularLobeSum none(below);
  none.add(lights.planes(), 0, lights.size(), 1);
  EXPECT_EQ(none.total(), Rgb{});
}

}  // namespace
}  // namespace relight
