// The designer's summary of a photometric file (light/photometry_summary.h): names from the
// file's header, lumens = ∫ I dω of what relight lights, LOR against the lamp lumens, and
// beam / field angles against the closed forms of I = I0 cos γ (cos γ = 0.5 at 60°, 0.1 at
// acos 0.1 = 84.26°).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "light/ies_parser.h"
#include "light/photometry_summary.h"
#include "photometry_test_support.h"

namespace relight {
namespace {

// An LM-63-2002 file: one lamp of `lamp_lm`, 25 W, a 0.6 m × 0.3 m rectangular opening and
// I(γ) = 1000 cos γ sampled every 1° on [0°, 90°]; with `up`, the same beam aimed up
// (γ measured from the downward axis, the light on [90°, 180°]).
std::string cosine_ies(double lamp_lm, bool up) {
  std::ostringstream s;
  s << "IESNA:LM-63-2002\n[TEST] relight\n[MANUFAC] Acme Lighting \n[LUMCAT] DL-100\n"
       "[LUMINAIRE] Cosine downlight\nTILT=NONE\n";
  s << "1 " << lamp_lm << " 1 91 1 1 2 0.3 0.6 0\n1 1 25\n";
  for (int g = 0; g <= 90; ++g) s << (up ? 90 + g : g) << (g % 10 == 9 ? "\n" : " ");
  s << "\n0\n";
  for (int g = 0; g <= 90; ++g) {
    const double gamma = (up ? 90 - g : g) * kPi / 180.0;
    s << std::max(0.0, 1000.0 * std::cos(gamma)) << (g % 10 == 9 ? "\n" : " ");
  }
  s << "\n";
  return s.str();
}

TEST(PhotometrySummary, CosineDownlightBeamAndFieldAnglesWithinAHundredthOfADegree) {
  const PhotometrySummary s = summarize_photometry(cosine_ies(4000, false), "cos.ies");
  EXPECT_EQ(s.format, "IES LM-63-2002");
  EXPECT_EQ(s.manufacturer, "Acme Lighting");
  EXPECT_EQ(s.catalogue, "DL-100");
  EXPECT_EQ(s.luminaire, "Cosine downlight");
  EXPECT_EQ(s.symmetry, CSymmetry::kAxial);
  EXPECT_NEAR(s.max_cd, 1000.0, 1e-9);
  // Linear interpolation between 1° samples of cos γ: the 50 % and 10 % crossings move by
  // well under 0.01°.
  EXPECT_NEAR(s.beam_angle_deg, 120.0, 0.01);
  EXPECT_NEAR(s.field_angle_deg, 2.0 * std::acos(0.1) * 180.0 / kPi, 0.01);
  // ∫ 1000 cos γ dω over the lower hemisphere = 1000 π lm; the 1° polyline is within 1e-4.
  EXPECT_NEAR(s.lumens, 1000.0 * kPi, 1000.0 * kPi * 1e-4);
  ASSERT_TRUE(s.lor.has_value());
  EXPECT_NEAR(*s.lor, s.lumens / 4000.0, 1e-12);
  ASSERT_TRUE(s.watts.has_value());
  EXPECT_DOUBLE_EQ(*s.watts, 25.0);
  EXPECT_EQ(s.opening.shape, OpeningShape::kRectangular);
  EXPECT_DOUBLE_EQ(s.opening.width_m, 0.3);
  EXPECT_DOUBLE_EQ(s.opening.length_m, 0.6);
  EXPECT_FALSE(s.absolute_photometry);
}

TEST(PhotometrySummary, AnUplightsBeamIsMeasuredFromTheUpwardAxis) {
  const PhotometrySummary up = summarize_photometry(cosine_ies(4000, true), "up.ies");
  EXPECT_NEAR(up.beam_angle_deg, 120.0, 0.01);
  EXPECT_NEAR(up.field_angle_deg, 2.0 * std::acos(0.1) * 180.0 / kPi, 0.01);
}

TEST(PhotometrySummary, AbsolutePhotometryHasNoLightOutputRatio) {
  const PhotometrySummary s = summarize_photometry(cosine_ies(-1, false), "abs.ies");
  EXPECT_TRUE(s.absolute_photometry);
  EXPECT_FALSE(s.lor.has_value());
  EXPECT_NEAR(s.lumens, 1000.0 * kPi, 1000.0 * kPi * 1e-4);
}

// The beam of a web whose C planes differ is the mean over half-planes: two half-planes of
// a bilateral file hold cos γ (crossing at 60°) and a narrower cos³ γ (crossing at
// acos(0.5^(1/3)) = 37.47°); every other C mixes them linearly, so the figure lies between.
TEST(PhotometrySummary, AnAsymmetricBeamLiesBetweenItsNarrowestAndWidestPlanes) {
  PhotometricWeb narrow_wide;
  std::vector<double> gamma, candela;
  for (int g = 0; g <= 90; ++g) gamma.push_back(g);
  for (int c = 0; c < 2; ++c) {
    for (int g = 0; g <= 90; ++g) {
      const double cg = std::cos(g * kPi / 180.0);
      candela.push_back(1000.0 * (c == 0 ? cg : cg * cg * cg));
    }
  }
  narrow_wide = make_web({0, 180}, gamma, candela, CSymmetry::kBilateralC0C180);
  const double beam = spread_angle_deg(narrow_wide, 0.5);
  EXPECT_GT(beam, 2 * 37.47 + 1);
  EXPECT_LT(beam, 120.0 - 1);
}

TEST(PhotometrySummary, EulumdatNamesLumensAndWattsComeFromTheFile) {
  const auto file = test::test_data("small_axial.ldt");
  const PhotometrySummary s = summarize_photometry_file(file);
  EXPECT_EQ(s.format, "EULUMDAT");
  EXPECT_EQ(s.manufacturer, "relight tests: valid small file");
  EXPECT_EQ(s.catalogue, "RL-1");
  EXPECT_EQ(s.luminaire, "relight test luminaire");
  EXPECT_EQ(s.symmetry, CSymmetry::kAxial);
  ASSERT_TRUE(s.watts.has_value());
  EXPECT_DOUBLE_EQ(*s.watts, 10.0);
  // 300, 200, 0 cd/klm at γ = 0°, 45°, 90° for 1000 lamp lumens.
  EXPECT_NEAR(s.max_cd, 300.0, 1e-9);
  const double flux = test::brute_force_flux([](double, double gamma) {
    const double g = gamma * 180.0 / kPi;
    if (g >= 90) return 0.0;
    return g <= 45 ? 300.0 - 100.0 * g / 45.0 : 200.0 * (90.0 - g) / 45.0;
  });
  EXPECT_NEAR(s.lumens, flux, flux * 1e-4);
  ASSERT_TRUE(s.lor.has_value());
  EXPECT_NEAR(*s.lor, s.lumens / 1000.0, 1e-12);
  // 50 % of 300 cd = 150 cd, reached at 45° + 50/200 of 45°; 10 % at 45° + 170/200 of 45°.
  EXPECT_NEAR(s.beam_angle_deg, 2 * (45.0 + 45.0 * 50.0 / 200.0), 1e-6);
  EXPECT_NEAR(s.field_angle_deg, 2 * (45.0 + 45.0 * 170.0 / 200.0), 1e-6);
}

TEST(PhotometrySummary, JsonHasEveryKeyOfTheInfoLine) {
  const nlohmann::json j = to_json(summarize_photometry(cosine_ies(4000, false), "cos.ies"));
  for (const char* key : {"manufacturer", "catalogue", "luminaire", "lumens", "watts", "lor",
                          "max_cd", "beam_angle_deg", "field_angle_deg", "symmetry", "opening_m"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["symmetry"], "axial");
  EXPECT_EQ(j["opening_m"]["shape"], "rectangular");
  EXPECT_DOUBLE_EQ(j["opening_m"]["length"].get<double>(), 0.6);
  const nlohmann::json abs = to_json(summarize_photometry(cosine_ies(-1, false), "a.ies"));
  EXPECT_TRUE(abs["lor"].is_null());
}

TEST(PhotometrySummary, OtherExtensionsAndBadFilesAreInputErrors) {
  test::expect_input_error([] { summarize_photometry(cosine_ies(4000, false), "lamp.txt"); },
                           {"lamp.txt", ".ies or .ldt"});
  std::string truncated = cosine_ies(4000, false);
  truncated.resize(truncated.size() / 2);
  test::expect_input_error([&] { summarize_photometry(truncated, "cut.ies"); }, {"cut.ies:"});
}

}  // namespace
}  // namespace relight
