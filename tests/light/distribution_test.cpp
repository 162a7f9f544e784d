// Distribution: analytic models against closed forms, evaluation by angles and by local
// direction, validation messages at the scene's JSON path, and file-based loading.
#include "light/distribution.h"

#include <gtest/gtest.h>

#include "photometry_test_support.h"

namespace relight {
namespace {

using test::expect_input_error;

DistributionSpec spec_of(DistributionType type) {
  DistributionSpec s;
  s.type = type;
  s.where = "scene.json:/luminaires/0/distribution";
  return s;
}

DistributionSpec cosine(double candela, double exponent, double cutoff_deg) {
  DistributionSpec s = spec_of(DistributionType::kCosinePower);
  s.candela = candela;
  s.exponent = exponent;
  s.cutoff_deg = cutoff_deg;
  return s;
}

DistributionSpec curve(std::vector<double> gamma_deg, std::vector<double> candela) {
  DistributionSpec s = spec_of(DistributionType::kCurve);
  s.gamma_deg = std::move(gamma_deg);
  s.curve_candela = std::move(candela);
  return s;
}

// Axisymmetric models: one C sample, a fine grid in γ so that steps (cut-offs, the end
// of a curve) cost little.
double brute_force(const Distribution& d) {
  return test::brute_force_flux([&](double c, double g) { return d.intensity(c, g); }, 200000, 1);
}

Vec3 direction(double c, double g) {
  return {std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), std::cos(g)};
}

TEST(Distribution, IsotropicFluxIs4PiI) {
  DistributionSpec s = spec_of(DistributionType::kIsotropic);
  s.candela = 120;
  const Distribution d = load_distribution(s);
  EXPECT_NEAR(d.flux_lm(), 4 * kPi * 120, 1e-9);
  EXPECT_NEAR(brute_force(d) / d.flux_lm(), 1.0, 1e-9);
  EXPECT_EQ(d.intensity(direction(1, 2)), 120.0);
  EXPECT_TRUE(d.axisymmetric());
  EXPECT_EQ(d.max_intensity(), 120.0);
  EXPECT_FALSE(d.rated_lumens());
  EXPECT_EQ(d.opening().shape, OpeningShape::kPoint);
}

TEST(Distribution, CosinePowerFluxIs2PiIOverNPlus1WithA90DegreeCutoff) {
  for (const double n : {0.0, 1.0, 2.0, 5.5, 40.0}) {
    const Distribution d = load_distribution(cosine(1000, n, 90));
    EXPECT_NEAR(d.flux_lm(), 2 * kPi * 1000 / (n + 1), 1e-9) << n;
    EXPECT_NEAR(brute_force(d) / d.flux_lm(), 1.0, 1e-4) << n;
  }
}

TEST(Distribution, CosinePowerCutoffBeyond90ChangesNothing) {
  const Distribution d = load_distribution(cosine(500, 2, 150));
  EXPECT_NEAR(d.flux_lm(), 2 * kPi * 500 / 3, 1e-9);
  EXPECT_EQ(d.intensity(0, radians(120)), 0.0);
}

TEST(Distribution, CosinePowerWithNarrowCutoff) {
  // 2πI(1 - cos^(n+1) θc)/(n+1), θc = 30°, n = 1: πI(1 - 3/4) = πI/4.
  const Distribution d = load_distribution(cosine(800, 1, 30));
  EXPECT_NEAR(d.flux_lm(), kPi * 800 / 4, 1e-9);
  EXPECT_NEAR(brute_force(d) / d.flux_lm(), 1.0, 1e-4);
  EXPECT_DOUBLE_EQ(d.intensity(0, radians(29.9)), 800 * std::cos(radians(29.9)));
  EXPECT_EQ(d.intensity(0, radians(30.1)), 0.0);
}

TEST(Distribution, CosinePowerByDirectionMatchesByAngles) {
  const Distribution d = load_distribution(cosine(300, 3, 70));
  for (const double g : {0.0, 0.3, 1.0, 1.2, 1.3, 2.0}) {
    EXPECT_NEAR(d.intensity(direction(0.4, g)), d.intensity(0.4, g), 1e-9) << g;
  }
}

TEST(Distribution, CurveIsLinearBetweenPointsAndZeroBeyondTheLast) {
  const Distribution d = load_distribution(curve({0, 30, 60}, {100, 50, 20}));
  EXPECT_DOUBLE_EQ(d.intensity(0, radians(15)), 75.0);
  EXPECT_DOUBLE_EQ(d.intensity(2, radians(45)), 35.0);
  EXPECT_DOUBLE_EQ(d.intensity(0, radians(60)), 20.0);
  EXPECT_EQ(d.intensity(0, radians(61)), 0.0);
  EXPECT_DOUBLE_EQ(d.intensity(direction(1, radians(15))), 75.0);
  EXPECT_EQ(d.max_intensity(), 100.0);
}

TEST(Distribution, CurveFluxMatchesClosedForms) {
  // Constant over the sphere: 4πI.
  EXPECT_NEAR(load_distribution(curve({0, 180}, {10, 10})).flux_lm(), 40 * kPi, 1e-9);
  // Constant over the lower hemisphere: 2πI.
  EXPECT_NEAR(load_distribution(curve({0, 90}, {10, 10})).flux_lm(), 20 * kPi, 1e-9);
  // I = I0·(1 - 2γ/π) on [0, π/2]: 2πI0·∫(1 - 2γ/π) sinγ dγ = 2πI0·(1 - 2/π).
  EXPECT_NEAR(load_distribution(curve({0, 90}, {10, 0})).flux_lm(), 20 * kPi * (1 - 2 / kPi), 1e-9);
  const Distribution d = load_distribution(curve({0, 10, 35, 80, 140}, {300, 280, 120, 40, 5}));
  EXPECT_NEAR(brute_force(d) / d.flux_lm(), 1.0, 1e-4);
}

TEST(Distribution, WebByDirectionMatchesByAngles) {
  const Distribution d{make_web({0, 90, 180, 270}, {0, 45, 90, 180},
                                {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16},
                                CSymmetry::kNone)};
  for (const double c : {0.0, 0.5, 2.0, 4.0, 6.0}) {
    for (const double g : {0.2, 0.9, 1.7, 3.0}) {  // at γ = 0 a direction has no C
      EXPECT_NEAR(d.intensity(direction(c, g)), d.intensity(c, g), 1e-9) << c << " " << g;
    }
  }
  EXPECT_NEAR(d.intensity(Vec3{0, 0, 1}), d.intensity(0, 0), 1e-12);
  EXPECT_FALSE(d.axisymmetric());
  EXPECT_EQ(d.max_intensity(), 16.0);
}

TEST(Distribution, LoadsIesAndLdtFiles) {
  DistributionSpec s = spec_of(DistributionType::kIes);
  s.file = test::test_data("bilateral_90_270_2019.ies");
  const Distribution ies = load_distribution(s);
  EXPECT_DOUBLE_EQ(*ies.rated_lumens(), 3000.0);
  EXPECT_EQ(ies.opening().shape, OpeningShape::kCircular);
  EXPECT_GT(ies.flux_lm(), 0.0);
  s.type = DistributionType::kLdt;
  s.file = test::test_data("small_axial.ldt");
  const Distribution ldt = load_distribution(s);
  EXPECT_TRUE(ldt.axisymmetric());
  EXPECT_DOUBLE_EQ(ldt.max_intensity(), 300.0);
}

TEST(Distribution, FileErrorsNameTheFileAndLine) {
  DistributionSpec s = spec_of(DistributionType::kIes);
  s.file = test::test_data("bad_truncated.ies");
  expect_input_error([&] { load_distribution(s); }, {"bad_truncated.ies:10:"});
  s.file = test::test_data("missing.ies");
  expect_input_error([&] { load_distribution(s); },
                     {"scene.json:/luminaires/0/distribution:", "missing.ies", "not found"});
  s.file.clear();
  expect_input_error([&] { load_distribution(s); }, {"scene.json:/luminaires/0/distribution:"});
}

TEST(Distribution, RejectsBadAnalyticParametersAtTheSpecPath) {
  const std::string where = "scene.json:/luminaires/0/distribution:";
  DistributionSpec iso = spec_of(DistributionType::kIsotropic);
  iso.candela = -1;
  expect_input_error([&] { load_distribution(iso); }, {where, "candela"});
  iso.candela = std::nan("");
  expect_input_error([&] { load_distribution(iso); }, {where, "candela"});
  expect_input_error([] { load_distribution(cosine(-5, 1, 90)); }, {where, "candela"});
  expect_input_error([] { load_distribution(cosine(5, -1, 90)); }, {where, "exponent"});
  expect_input_error([] { load_distribution(cosine(5, 1, 0)); }, {where, "cutoff_deg"});
  expect_input_error([] { load_distribution(cosine(5, 1, 180.5)); }, {where, "cutoff_deg"});
  expect_input_error([] { load_distribution(curve({0, 30}, {1})); }, {where, "candela has 1"});
  expect_input_error([] { load_distribution(curve({0}, {1})); }, {where, "at least 2"});
  expect_input_error([] { load_distribution(curve({5, 30}, {1, 1})); }, {where, "start at 0"});
  expect_input_error([] { load_distribution(curve({0, 30, 30}, {1, 1, 1})); }, {where, "ascend"});
  expect_input_error([] { load_distribution(curve({0, 190}, {1, 1})); }, {where, "180"});
  expect_input_error([] { load_distribution(curve({0, 90}, {1, -1})); }, {where, "candela[1]"});
}

}  // namespace
}  // namespace relight
