// Reconstruction from valid domains (Sun 2005 §3.3.5, Eq. 2.13 with b = 1):
// inside exactly one domain the sample's vector itself; inside two, the 1/d-weighted mean in
// closed form; at a sample's position that sample alone; in none, the caller's fallback; and
// random configurations against a brute-force Eq. 2.13 over every sample whose sphere contains
// the point.
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "sh_rows.h"
#include "sources/emitters/valid_domain_reconstruction.h"

namespace relight {
namespace {

constexpr std::size_t kCoefficients = 4;  // order 2

std::vector<Rgb> vector_of(double base) {
  std::vector<Rgb> sh;
  for (std::size_t j = 0; j < kCoefficients; ++j) {
    const double v = base + static_cast<double>(j);
    sh.push_back({v, -2 * v, 0.5 * v + 1});
  }
  return sh;
}

using testing::expect_row;
using testing::mix;

std::vector<Rgb> reconstruct(const std::vector<IncidentSample>& samples,
                             const std::vector<Vec3>& points,
                             const std::vector<std::uint32_t>& fallback) {
  const LinearOctree octree = build_sample_octree(samples, points);
  std::vector<Rgb> out(points.size() * kCoefficients);
  reconstruct_valid_domain(samples, octree, points, fallback, out);
  return out;
}

// A at the origin and B at (1, 0, 0), both with domains of radius 2 (overlapping); C far away
// at (6, 0, 0) with radius 1.
std::vector<IncidentSample> three_samples() {
  return {{{0, 0, 0}, 2.0, vector_of(1)},
          {{1, 0, 0}, 2.0, vector_of(10)},
          {{6, 0, 0}, 1.0, vector_of(-5)}};
}

TEST(ValidDomainReconstruction, InsideExactlyOneDomainIsThatSample) {
  const auto samples = three_samples();
  const std::vector<Vec3> points{{6.3, 0.2, -0.1}, {-1.5, 0.5, 0}, {6, 0, 0.999}};
  const std::vector<Rgb> out = reconstruct(samples, points, {0, 1, 0});
  expect_row(out, 0, samples[2].sh, 1e-12);  // only C's domain
  expect_row(out, 1, samples[0].sh, 1e-12);  // only A's (2.55 from B: outside its radius 2)
  expect_row(out, 2, samples[2].sh, 1e-12);
}

TEST(ValidDomainReconstruction, TwoOverlappingDomainsGiveTheInverseDistanceMean) {
  const auto samples = three_samples();
  // d_A = 0.25, d_B = 0.75: w_A = (1/0.25) / (1/0.25 + 1/0.75) = 3/4.
  // (0.5, 0.5, 0): d_A = d_B, the plain mean. (-0.5, 1, 0): d_A = √1.25, d_B = √3.25.
  const std::vector<Vec3> points{{0.25, 0, 0}, {0.5, 0.5, 0}, {-0.5, 1, 0}};
  const std::vector<Rgb> out = reconstruct(samples, points, {2, 2, 2});
  expect_row(out, 0, mix(samples[0].sh, 0.75, samples[1].sh, 0.25), 1e-12);
  expect_row(out, 1, mix(samples[0].sh, 0.5, samples[1].sh, 0.5), 1e-12);
  const double wa = std::sqrt(3.25) / (std::sqrt(1.25) + std::sqrt(3.25));
  expect_row(out, 2, mix(samples[0].sh, wa, samples[1].sh, 1 - wa), 1e-12);
}

TEST(ValidDomainReconstruction, AtASamplePositionThatSampleAlone) {
  const auto samples = three_samples();
  const std::vector<Vec3> points{{1, 0, 0}, {0, 0, 0}};  // each inside the other's domain too
  const std::vector<Rgb> out = reconstruct(samples, points, {2, 2});
  expect_row(out, 0, samples[1].sh, 0);
  expect_row(out, 1, samples[0].sh, 0);
}

TEST(ValidDomainReconstruction, NoDomainContainingThePointUsesTheFallback) {
  const auto samples = three_samples();
  // (3.5, 0, 0): 1.5 beyond B's radius, 1.5 short of C's; (10, 0, 0) far beyond everything.
  const std::vector<Vec3> points{{3.5, 0, 0}, {10, 0, 0}, {2.5, 0, 0}};
  const std::vector<Rgb> out = reconstruct(samples, points, {1, 0, 2});
  expect_row(out, 0, samples[1].sh, 0);
  expect_row(out, 1, samples[0].sh, 0);
  expect_row(out, 2, samples[1].sh, 1e-12);  // d_B = 1.5 < 2: B's domain, the fallback unused
}

TEST(ValidDomainReconstruction, MatchesBruteForceOverRandomDomains) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 10), log_r(-3, 1.5), value(-1, 1);
  std::vector<IncidentSample> samples;
  for (int i = 0; i < 300; ++i) {
    IncidentSample s{{u(rng), u(rng), u(rng)}, std::exp2(log_r(rng)), {}};
    for (std::size_t j = 0; j < kCoefficients; ++j) {
      s.sh.push_back({value(rng), value(rng), value(rng)});
    }
    samples.push_back(s);
  }
  std::vector<Vec3> points;
  std::vector<std::uint32_t> fallback;
  for (int p = 0; p < 4000; ++p) {
    points.push_back({u(rng), u(rng), u(rng)});
    fallback.push_back(static_cast<std::uint32_t>(p) % 300);
  }
  const std::vector<Rgb> out = reconstruct(samples, points, fallback);
  std::size_t interpolated = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::vector<Rgb> expected(kCoefficients);
    double total = 0;
    for (const IncidentSample& s : samples) {
      const double d = length(points[p] - s.position);
      if (d > s.radius) continue;
      total += 1 / d;
      for (std::size_t j = 0; j < kCoefficients; ++j) expected[j] += (1 / d) * s.sh[j];
    }
    if (total == 0) {
      expected = samples[fallback[p]].sh;
    } else {
      ++interpolated;
      for (Rgb& c : expected) c = c / total;
    }
    expect_row(out, p, expected, 1e-12);
  }
  EXPECT_GT(interpolated, 1000u);
  EXPECT_LT(interpolated, points.size());  // the fallback is exercised too
}

TEST(ValidDomainReconstruction, RejectsInconsistentSizes) {
  auto samples = three_samples();
  const std::vector<Vec3> points{{0, 0, 0}, {1, 1, 1}};
  const LinearOctree octree = build_sample_octree(samples, points);
  std::vector<Rgb> out(points.size() * kCoefficients);
  const std::vector<std::uint32_t> fallback{0, 0};
  const std::vector<std::uint32_t> short_fallback{0};
  const std::vector<std::uint32_t> bad_fallback{0, 3};
  std::vector<Rgb> short_out(out.size() - 1);
  EXPECT_THROW(reconstruct_valid_domain(samples, octree, points, short_fallback, out),
               std::invalid_argument);
  EXPECT_THROW(reconstruct_valid_domain(samples, octree, points, bad_fallback, out),
               std::invalid_argument);
  EXPECT_THROW(reconstruct_valid_domain(samples, octree, points, fallback, short_out),
               std::invalid_argument);
  samples[1].sh.pop_back();
  EXPECT_THROW(reconstruct_valid_domain(samples, octree, points, fallback, out),
               std::invalid_argument);
}

}  // namespace
}  // namespace relight
