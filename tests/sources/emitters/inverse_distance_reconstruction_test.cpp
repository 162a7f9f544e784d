// The baseline reconstruction over all samples, Eq. 2.12–2.13 of Sun 2005: the
// two-sample weights in closed form for b = 1, 2 and 3 (w_A = d_B^b / (d_A^b + d_B^b)),
// exactness at a sample's position, the default b = 2, and random configurations against a
// direct evaluation of Eq. 2.13.
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "sh_rows.h"
#include "sources/emitters/inverse_distance_reconstruction.h"

namespace relight {
namespace {

constexpr std::size_t kCoefficients = 9;  // order 3

std::vector<Rgb> vector_of(double base) {
  std::vector<Rgb> sh;
  for (std::size_t j = 0; j < kCoefficients; ++j) {
    const double v = base + 0.5 * static_cast<double>(j);
    sh.push_back({v, 3 - v, 2 * v});
  }
  return sh;
}

using testing::expect_row;
using testing::mix;

const std::vector<IncidentSample> kTwo{{{0, 0, 0}, 0, vector_of(1)}, {{1, 0, 0}, 0, vector_of(7)}};

TEST(InverseDistanceReconstruction, TwoSampleWeightsInClosedForm) {
  // (0.25, 0, 0): d_A = 1/4, d_B = 3/4. b = 1: w_A = 3/4; b = 2: 9/10; b = 3: 27/28.
  // (0.5, 2, 0): d_A = √4.25 = d_B: 1/2 for every b. (−1, 1, 0): d_A = √2, d_B = √5.
  const std::vector<Vec3> points{{0.25, 0, 0}, {0.5, 2, 0}, {-1, 1, 0}};
  std::vector<Rgb> out(points.size() * kCoefficients);
  const double expected_near[] = {0.75, 0.9, 27.0 / 28.0};
  for (int b = 1; b <= 3; ++b) {
    reconstruct_inverse_distance(kTwo, points, out, b);
    const double wa = expected_near[b - 1];
    expect_row(out, 0, mix(kTwo[0].sh, wa, kTwo[1].sh, 1 - wa), 1e-12);
    expect_row(out, 1, mix(kTwo[0].sh, 0.5, kTwo[1].sh, 0.5), 1e-12);
    const double da = std::pow(2.0, 0.5 * b), db = std::pow(5.0, 0.5 * b);
    expect_row(out, 2, mix(kTwo[0].sh, db / (da + db), kTwo[1].sh, da / (da + db)), 1e-12);
  }
}

TEST(InverseDistanceReconstruction, DefaultExponentIsTwo) {
  const std::vector<Vec3> points{{0.25, 0, 0}};
  std::vector<Rgb> out(kCoefficients);
  reconstruct_inverse_distance(kTwo, points, out);
  expect_row(out, 0, mix(kTwo[0].sh, 0.9, kTwo[1].sh, 0.1), 1e-12);
}

TEST(InverseDistanceReconstruction, ExactAtASamplePosition) {
  const std::vector<Vec3> points{{1, 0, 0}, {0, 0, 0}};
  std::vector<Rgb> out(points.size() * kCoefficients);
  for (const double b : {1.0, 2.0, 0.5}) {
    reconstruct_inverse_distance(kTwo, points, out, b);
    expect_row(out, 0, kTwo[1].sh, 0);
    expect_row(out, 1, kTwo[0].sh, 0);
  }
}

TEST(InverseDistanceReconstruction, MatchesEquationTwoThirteenOverRandomSamples) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<IncidentSample> samples;
  for (int i = 0; i < 64; ++i) {
    IncidentSample s{{u(rng), u(rng), u(rng)}, 0, {}};
    for (std::size_t j = 0; j < kCoefficients; ++j) s.sh.push_back({u(rng), u(rng), u(rng)});
    samples.push_back(s);
  }
  std::vector<Vec3> points;
  for (int p = 0; p < 500; ++p) points.push_back({u(rng), u(rng), u(rng)});
  std::vector<Rgb> out(points.size() * kCoefficients);
  for (const double b : {1.0, 2.0, 4.0}) {
    reconstruct_inverse_distance(samples, points, out, b);
    for (std::size_t p = 0; p < points.size(); ++p) {
      double sum = 0;  // Σ_j ‖p − x_j‖^−b
      for (const IncidentSample& s : samples) sum += std::pow(length(points[p] - s.position), -b);
      std::vector<Rgb> expected(kCoefficients);
      for (const IncidentSample& s : samples) {
        const double w = std::pow(length(points[p] - s.position), -b) / sum;
        for (std::size_t j = 0; j < kCoefficients; ++j) expected[j] += w * s.sh[j];
      }
      expect_row(out, p, expected, 1e-12);
    }
  }
}

TEST(InverseDistanceReconstruction, RejectsInconsistentInput) {
  const std::vector<Vec3> points{{0.5, 0, 0}};
  std::vector<Rgb> out(kCoefficients);
  std::vector<Rgb> short_out(kCoefficients - 1);
  EXPECT_THROW(reconstruct_inverse_distance(kTwo, points, short_out), std::invalid_argument);
  EXPECT_THROW(reconstruct_inverse_distance(kTwo, points, out, -1), std::invalid_argument);
  EXPECT_THROW(reconstruct_inverse_distance({}, points, out), std::invalid_argument);
  auto uneven = kTwo;
  uneven[0].sh.pop_back();
  EXPECT_THROW(reconstruct_inverse_distance(uneven, points, out), std::invalid_argument);
}

}  // namespace
}  // namespace relight
