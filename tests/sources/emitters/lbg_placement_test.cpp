// The LBG/"ICP" sample placement of Sun 2005's baseline (§2.2.5, [LBG80]): the
// number of codewords, count 1 = the centroid, every codeword the mean of its Voronoi cell
// (brute force, within 1e-9) once the Lloyd iterations have converged, bit-for-bit determinism
// for a seed on any number of threads, two separated clouds found by count 2, and a count that
// is not a power of two splitting the cluster of largest distortion.
#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "sources/emitters/lbg_placement.h"

namespace relight {
namespace {

std::vector<Vec3> uniform_cloud(Vec3 centre, double half_width, int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-half_width, half_width);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.push_back(centre + Vec3{u(rng), u(rng), u(rng)});
  return points;
}

Vec3 centroid(std::span<const Vec3> points) {
  Vec3 sum{};
  for (const Vec3& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

void expect_near(Vec3 a, Vec3 b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Eight tight blobs at the corners of a box (σ = 0.05, 1.5 apart at least) and 150 points
// spread through the box, so that the Voronoi cells are not trivially the blobs.
std::vector<Vec3> blobs() {
  std::mt19937 rng(41);
  std::normal_distribution<double> n(0, 0.05);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> points;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c{1.5 * (corner & 1), 2.0 * ((corner >> 1) & 1), 2.5 * ((corner >> 2) & 1)};
    for (int i = 0; i < 100 + 20 * corner; ++i) points.push_back(c + Vec3{n(rng), n(rng), n(rng)});
  }
  for (int i = 0; i < 150; ++i) points.push_back({1.5 * u(rng), 2.0 * u(rng), 2.5 * u(rng)});
  return points;
}

// Brute-force Voronoi cells of the codewords (ties to the lower index): each codeword within
// 1e-9 of its cell's mean, and no cell empty.
void expect_voronoi_means(std::span<const Vec3> points, const std::vector<Vec3>& codewords) {
  std::vector<Vec3> sums(codewords.size());
  std::vector<int> counts(codewords.size());
  for (const Vec3& p : points) {
    std::size_t best = 0;
    for (std::size_t c = 1; c < codewords.size(); ++c) {
      if (dot(p - codewords[c], p - codewords[c]) < dot(p - codewords[best], p - codewords[best])) {
        best = c;
      }
    }
    sums[best] += p;
    ++counts[best];
  }
  for (std::size_t c = 0; c < codewords.size(); ++c) {
    ASSERT_GT(counts[c], 0) << "codeword " << c;
    expect_near(codewords[c], sums[c] / counts[c], 1e-9);
  }
}

TEST(LbgPlacement, ReturnsTheRequestedNumberOfCodewords) {
  const std::vector<Vec3> points = uniform_cloud({1, 2, 3}, 1, 2000, 1);
  for (const int count : {1, 2, 3, 5, 8, 13, 64}) {
    EXPECT_EQ(lbg_sample_positions(points, count, 7).size(), static_cast<std::size_t>(count));
  }
  EXPECT_TRUE(lbg_sample_positions(points, 0, 7).empty());
  EXPECT_THROW(lbg_sample_positions({}, 4, 7), std::invalid_argument);
}

TEST(LbgPlacement, OneCodewordIsTheCentroid) {
  const std::vector<Vec3> points = uniform_cloud({-4, 0, 9}, 2, 1000, 2);
  expect_near(lbg_sample_positions(points, 1, 3).front(), centroid(points), 1e-12);
}

TEST(LbgPlacement, EveryCodewordIsTheMeanOfItsVoronoiCell) {
  const std::vector<Vec3> points = blobs();
  for (const int count : {8, 6, 11}) {
    SCOPED_TRACE(count);
    expect_voronoi_means(points, lbg_sample_positions(points, count, 5));
  }
}

TEST(LbgPlacement, ManyCodewordsAreMeansOfTheirVoronoiCells) {
  // 64 tight blobs on a 4 × 4 × 4 grid and a sparse scatter: deep enough a k-d tree over the
  // codewords that a wrong nearest codeword would show.
  std::mt19937 rng(43);
  std::normal_distribution<double> n(0, 0.03);
  std::uniform_real_distribution<double> u(0, 3);
  std::vector<Vec3> points;
  for (int cell = 0; cell < 64; ++cell) {
    const Vec3 c{double(cell % 4), double((cell / 4) % 4), double(cell / 16)};
    for (int i = 0; i < 40 + cell % 7; ++i) points.push_back(c + Vec3{n(rng), n(rng), n(rng)});
  }
  for (int i = 0; i < 300; ++i) points.push_back({u(rng), u(rng), u(rng)});
  expect_voronoi_means(points, lbg_sample_positions(points, 64, 13));
  expect_voronoi_means(points, lbg_sample_positions(points, 40, 13));
}

TEST(LbgPlacement, DeterministicForASeedWhateverTheThreads) {
  const std::vector<Vec3> points = uniform_cloud({0, 0, 0}, 1, 5000, 3);
  for (const int count : {7, 32}) {
    const std::vector<Vec3> a = lbg_sample_positions(points, count, 11);
    const std::vector<Vec3> b = lbg_sample_positions(points, count, 11);
    EXPECT_EQ(a, b);  // bit for bit
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(lbg_sample_positions(points, count, 11), a);
  }
}

TEST(LbgPlacement, TwoSeparatedCloudsGetOneCodewordEach) {
  const std::vector<Vec3> a = uniform_cloud({-10, 0, 0}, 1, 500, 4);
  const std::vector<Vec3> b = uniform_cloud({10, 2, -1}, 0.5, 300, 5);
  std::vector<Vec3> points = a;
  points.insert(points.end(), b.begin(), b.end());
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    std::vector<Vec3> codewords = lbg_sample_positions(points, 2, seed);
    ASSERT_EQ(codewords.size(), 2u);
    std::sort(codewords.begin(), codewords.end(), [](Vec3 p, Vec3 q) { return p.x < q.x; });
    expect_near(codewords[0], centroid(a), 1e-9);
    expect_near(codewords[1], centroid(b), 1e-9);
  }
}

TEST(LbgPlacement, UnevenCountSplitsTheClusterOfLargestDistortion) {
  // A wide cloud and a tight one: with 3 codewords the wide one is split, the tight one keeps
  // one codeword at its centroid.
  const std::vector<Vec3> wide = uniform_cloud({-10, 0, 0}, 2, 600, 6);
  const std::vector<Vec3> tight = uniform_cloud({10, 0, 0}, 0.1, 600, 7);
  std::vector<Vec3> points = tight;
  points.insert(points.end(), wide.begin(), wide.end());
  std::vector<Vec3> codewords = lbg_sample_positions(points, 3, 9);
  ASSERT_EQ(codewords.size(), 3u);
  std::sort(codewords.begin(), codewords.end(), [](Vec3 p, Vec3 q) { return p.x < q.x; });
  expect_near(codewords[2], centroid(tight), 1e-9);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(length(codewords[i] - Vec3{-10, 0, 0}), 2.0) << i;  // both inside the wide cloud
  }
}

}  // namespace
}  // namespace relight
