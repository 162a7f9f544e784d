// Real SH (math/sh.h): orthonormality by exact quadrature, closed forms and the sign
// convention, agreement with the angular definition, pole behaviour, projection.
#include "math/sh.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "math/legendre.h"
#include "math/sampling.h"
#include "math/test_util.h"

namespace relight {
namespace {

// Gram matrix G_ij = Σ_k w_k Y_i(d_k) Y_j(d_k) with a rule exact to degree 2(order − 1).
Eigen::MatrixXd gram_matrix(int order) {
  const SphereQuadrature q = sphere_quadrature_exact_to_degree(2 * (order - 1));
  const int count = sh_count(order);
  Eigen::MatrixXd y(q.directions.size(), count);
  std::vector<double> row(count);
  for (std::size_t k = 0; k < q.directions.size(); ++k) {
    sh_eval(order, q.directions[k], row);
    const double sw = std::sqrt(q.weights[k]);
    for (int i = 0; i < count; ++i) y(k, i) = sw * row[i];
  }
  return y.transpose() * y;
}

TEST(ShOrthonormality, AllPairsUpToBand15By1e6) {
  const Eigen::MatrixXd g = gram_matrix(16);
  const double err = (g - Eigen::MatrixXd::Identity(256, 256)).cwiseAbs().maxCoeff();
  EXPECT_LT(err, 1e-6);
  EXPECT_LT(err, 1e-12);  // in fact to rounding
}

TEST(ShOrthonormality, AllPairsUpToBand31By1e11) {
  const Eigen::MatrixXd g = gram_matrix(32);
  const double err = (g - Eigen::MatrixXd::Identity(1024, 1024)).cwiseAbs().maxCoeff();
  EXPECT_LT(err, 1e-11);
}

TEST(ShOrthonormality, QuadratureWeightsSumTo4Pi) {
  for (int degree : {0, 1, 7, 30, 62}) {
    const SphereQuadrature q = sphere_quadrature_exact_to_degree(degree);
    double sum = 0.0;
    for (double w : q.weights) sum += w;
    EXPECT_NEAR(sum, 4 * kPi, 1e-12);
  }
}

TEST(ShEval, ClosedFormsWithoutCondonShortleyPhaseTo1e14) {
  Pcg32 rng(1, 2);
  std::vector<double> y(sh_count(4));
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 d = test::random_direction(rng);
    const double x = d.x, yy = d.y, z = d.z;
    sh_eval(4, d, y);
    const double c1 = std::sqrt(3 / (4 * kPi));
    EXPECT_NEAR(y[sh_index(0, 0)], 0.5 / std::sqrt(kPi), 1e-14);
    EXPECT_NEAR(y[sh_index(1, -1)], c1 * yy, 1e-14);
    EXPECT_NEAR(y[sh_index(1, 0)], c1 * z, 1e-14);
    EXPECT_NEAR(y[sh_index(1, 1)], c1 * x, 1e-14);
    EXPECT_NEAR(y[sh_index(2, -2)], 0.5 * std::sqrt(15 / kPi) * x * yy, 1e-14);
    EXPECT_NEAR(y[sh_index(2, -1)], 0.5 * std::sqrt(15 / kPi) * yy * z, 1e-14);
    EXPECT_NEAR(y[sh_index(2, 0)], 0.25 * std::sqrt(5 / kPi) * (3 * z * z - 1), 1e-14);
    EXPECT_NEAR(y[sh_index(2, 1)], 0.5 * std::sqrt(15 / kPi) * x * z, 1e-14);
    EXPECT_NEAR(y[sh_index(2, 2)], 0.25 * std::sqrt(15 / kPi) * (x * x - yy * yy), 1e-14);
    const double c3 = 0.25 * std::sqrt(35 / (2 * kPi));
    EXPECT_NEAR(y[sh_index(3, -3)], c3 * (3 * x * x - yy * yy) * yy, 1e-14);
    EXPECT_NEAR(y[sh_index(3, 3)], c3 * (x * x - 3 * yy * yy) * x, 1e-14);
    EXPECT_NEAR(y[sh_index(3, 0)], 0.25 * std::sqrt(7 / kPi) * (5 * z * z * z - 3 * z), 1e-14);
  }
}

TEST(ShEval, MatchesAngularDefinitionUpToBand31To1e12) {
  const int order = 32;
  Pcg32 rng(3, 4);
  std::vector<double> y(sh_count(order)), p(assoc_legendre_count(order));
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 d = test::random_direction(rng);
    sh_eval(order, d, y);
    assoc_legendre_normalized(order, d.z, p);
    const double phi = std::atan2(d.y, d.x);
    for (int l = 0; l < order; ++l) {
      EXPECT_NEAR(y[sh_index(l, 0)], p[assoc_legendre_index(l, 0)], 1e-12);
      for (int m = 1; m <= l; ++m) {
        const double pb = std::sqrt(2.0) * p[assoc_legendre_index(l, m)];
        EXPECT_NEAR(y[sh_index(l, m)], pb * std::cos(m * phi), 1e-12) << l << " " << m;
        EXPECT_NEAR(y[sh_index(l, -m)], pb * std::sin(m * phi), 1e-12) << l << " " << m;
      }
    }
  }
}

TEST(ShEval, PolesGiveZonalValuesOnly) {
  const int order = 32;
  std::vector<double> y(sh_count(order));
  for (double s : {1.0, -1.0}) {
    sh_eval(order, {0, 0, s}, y);
    for (int l = 0; l < order; ++l)
      for (int m = -l; m <= l; ++m) {
        const double expected = m == 0 ? std::sqrt((2 * l + 1) / (4 * kPi)) * std::pow(s, l) : 0;
        EXPECT_NEAR(y[sh_index(l, m)], expected, 1e-13);
      }
  }
}

TEST(ShEval, EvaluateAndAddSampleAgreeWithEvalTo1e13) {
  const int order = 20;
  Pcg32 rng(5, 6);
  const std::vector<double> c = test::random_coefficients(rng, order);
  std::vector<Rgb> crgb(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) crgb[i] = {c[i], 2 * c[i], -c[i]};
  std::vector<double> y(sh_count(order));
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 d = test::random_direction(rng);
    sh_eval(order, d, y);
    double dotp = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) dotp += c[i] * y[i];
    EXPECT_NEAR(sh_evaluate(c, d), dotp, 1e-12);
    const Rgb e = sh_evaluate(crgb, d);
    EXPECT_NEAR(e.r, dotp, 1e-12);
    EXPECT_NEAR(e.g, 2 * dotp, 1e-12);
    EXPECT_NEAR(e.b, -dotp, 1e-12);
    std::vector<double> acc(sh_count(order), 1.0);
    sh_add_sample(d, 0.5, acc);
    for (std::size_t i = 0; i < acc.size(); ++i) EXPECT_NEAR(acc[i], 1.0 + 0.5 * y[i], 1e-13);
  }
}

TEST(ShProjection, RecoversBandLimitedCoefficientsTo1e12) {
  Pcg32 rng(7, 8);
  for (int order : {1, 2, 5, 16}) {
    const std::vector<double> c = test::random_coefficients(rng, order);
    const auto f = [&](Vec3 d) { return sh_evaluate(c, d); };
    EXPECT_LT(test::max_abs_diff(sh_project(order, f), c), 1e-12) << order;
    // Projecting onto fewer bands keeps exactly the lower bands.
    const int low = (order + 1) / 2;
    const std::vector<double> p = sh_project(low, f, order);
    EXPECT_LT(test::max_abs_diff(p, std::vector<double>(c.begin(), c.begin() + low * low)), 1e-12);
  }
  // RGB.
  const std::vector<double> c = test::random_coefficients(rng, 6);
  const auto f = [&](Vec3 d) { return Rgb{sh_evaluate(c, d), 0.5, -sh_evaluate(c, d)}; };
  const std::vector<Rgb> p = sh_project_rgb(6, f, sphere_quadrature_exact_to_degree(10));
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(p[i].r, c[i], 1e-12);
    EXPECT_NEAR(p[i].g, i == 0 ? 0.5 * std::sqrt(4 * kPi) : 0.0, 1e-12);
    EXPECT_NEAR(p[i].b, -c[i], 1e-12);
  }
}

}  // namespace
}  // namespace relight
