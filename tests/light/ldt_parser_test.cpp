// EULUMDAT parsing: every Isym, both lamp-set orders, cd/klm → cd, absolute photometry,
// openings, and bad input reported as "FILE:LINE: reason".
#include "light/ldt_parser.h"

#include <gtest/gtest.h>

#include <cstdint>

#include <sstream>

#include "photometry_test_support.h"

namespace relight {
namespace {

using test::expect_input_error;
using test::test_data;

struct LdtSpec {
  int isym = 1;
  int mc = 1;
  std::vector<double> c = {0};
  std::vector<double> gamma = {0, 90};
  std::vector<std::string> lamp_lines = {"1", "LED", "1000", "3000K", "1A", "10"};
  int lamp_sets = 1;
  std::string lorl = "80";
  std::string cfli = "1";
  std::string luminous_length = "0", luminous_width = "0", luminous_height = "0";
  std::vector<std::string> values = {"300", "100"};
};

// Lines 1..25, 26 (lamp sets), lamp lines from 27, then 10 direct ratios, C, γ, values.
std::string ldt_text(const LdtSpec& s) {
  std::ostringstream o;
  o << "relight unit test\n1\n" << s.isym << "\n" << s.mc << "\n0\n" << s.gamma.size() << "\n0\n";
  o << "report\nluminaire\nnumber\nfile.ldt\ndate\n1000\n500\n100\n";
  o << s.luminous_length << "\n" << s.luminous_width << "\n";
  for (int i = 0; i < 4; ++i) o << s.luminous_height << "\n";
  o << "100\n" << s.lorl << "\n" << s.cfli << "\n0\n" << s.lamp_sets << "\n";
  for (const auto& l : s.lamp_lines) o << l << "\n";
  for (int i = 0; i < 10; ++i) o << "0.5\n";
  for (const double c : s.c) o << c << "\n";
  for (const double g : s.gamma) o << g << "\n";
  for (const auto& v : s.values) o << v << "\n";
  return o.str();
}

std::vector<std::string> numbered(int planes, int ng) {
  std::vector<std::string> v;
  for (int p = 0; p < planes; ++p) {
    for (int g = 0; g < ng; ++g) v.push_back(std::to_string(100 * (p + 1) + g));
  }
  return v;
}

std::size_t index_of(const std::vector<double>& v, double x) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::abs(v[i] - x) < 1e-9) return i;
  }
  ADD_FAILURE() << "angle " << x << " missing";
  return 0;
}

// The web value at (C, γ index) divided by the cd/klm → cd factor (1 for 1000 lm).
double stored(const PhotometricWeb& w, double c, std::size_t ig) {
  return w.at(index_of(w.c_deg, c), ig);
}

LdtSpec eight_planes(int isym, int stored_planes) {
  LdtSpec s;
  s.isym = isym;
  s.mc = 8;
  s.c = {0, 45, 90, 135, 180, 225, 270, 315};
  s.values = numbered(stored_planes, 2);
  return s;
}

TEST(LdtParser, NoSymmetryStoresEveryPlane) {
  const auto w = make_ldt_web(parse_ldt(ldt_text(eight_planes(0, 8)), "i0.ldt"));
  for (int p = 0; p < 8; ++p) EXPECT_EQ(stored(w, 45.0 * p, 1), 100.0 * (p + 1) + 1);
  EXPECT_EQ(stored(w, 360, 0), 100.0);
}

TEST(LdtParser, Isym1StoresOnePlaneForEveryC) {
  const auto w = make_ldt_web(parse_ldt(ldt_text(eight_planes(1, 1)), "i1.ldt"));
  EXPECT_EQ(w.c_deg, (std::vector<double>{0, 360}));
  EXPECT_DOUBLE_EQ(intensity(w, radians(200), radians(90)), 101.0);
}

TEST(LdtParser, Isym2StoresC0ToC180AndMirrors) {
  const auto d = parse_ldt(ldt_text(eight_planes(2, 5)), "i2.ldt");
  EXPECT_EQ(ldt_stored_planes(d), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  const auto w = make_ldt_web(d);
  EXPECT_EQ(stored(w, 135, 0), 400.0);
  EXPECT_EQ(stored(w, 225, 0), 400.0);  // I(225) = I(135)
  EXPECT_EQ(stored(w, 315, 1), 201.0);  // I(315) = I(45)
  EXPECT_EQ(stored(w, 180, 1), 501.0);
}

TEST(LdtParser, Isym3StoresC270ThroughC0ToC90AndMirrors) {
  const auto d = parse_ldt(ldt_text(eight_planes(3, 5)), "i3.ldt");
  EXPECT_EQ(ldt_stored_planes(d), (std::vector<std::size_t>{6, 7, 0, 1, 2}));
  const auto w = make_ldt_web(d);
  EXPECT_EQ(stored(w, 270, 0), 100.0);  // first stored plane
  EXPECT_EQ(stored(w, 315, 0), 200.0);
  EXPECT_EQ(stored(w, 0, 0), 300.0);
  EXPECT_EQ(stored(w, 45, 0), 400.0);
  EXPECT_EQ(stored(w, 90, 0), 500.0);
  EXPECT_EQ(stored(w, 135, 0), 400.0);  // I(135) = I(45)
  EXPECT_EQ(stored(w, 180, 1), 301.0);  // I(180) = I(0)
  EXPECT_EQ(stored(w, 225, 1), 201.0);  // I(225) = I(315)
}

TEST(LdtParser, Isym4StoresC0ToC90AndMirrorsTwice) {
  const auto w = make_ldt_web(parse_ldt(ldt_text(eight_planes(4, 3)), "i4.ldt"));
  for (const double c : {45.0, 135.0, 225.0, 315.0}) EXPECT_EQ(stored(w, c, 1), 201.0) << c;
  for (const double c : {0.0, 180.0, 360.0}) EXPECT_EQ(stored(w, c, 1), 101.0) << c;
  for (const double c : {90.0, 270.0}) EXPECT_EQ(stored(w, c, 1), 301.0) << c;
}

TEST(LdtParser, CandelaAreCdPerKlmTimesLampFluxTimesConversionFactor) {
  LdtSpec s;
  s.lamp_lines = {"2", "T5", "2500", "840", "1B", "60"};
  s.cfli = "1.2";
  const auto d = parse_ldt(ldt_text(s), "flux.ldt");
  EXPECT_DOUBLE_EQ(ldt_candela_scale(d), 1.2 * 2.5);
  const auto w = make_ldt_web(d);
  EXPECT_DOUBLE_EQ(intensity(w, 0, 0), 300 * 3.0);
  ASSERT_TRUE(w.rated_lumens);
  EXPECT_DOUBLE_EQ(*w.rated_lumens, 0.8 * 2500);  // LORL × lamp flux
  EXPECT_FALSE(w.absolute_photometry);
}

TEST(LdtParser, NegativeLampCountMarksAbsolutePhotometry) {
  LdtSpec s;
  s.lamp_lines = {"-1", "LED module", "3200", "4000K", "1A", "28"};
  s.lorl = "100";
  const auto w = make_ldt_web(parse_ldt(ldt_text(s), "abs.ldt"));
  EXPECT_TRUE(w.absolute_photometry);
  EXPECT_DOUBLE_EQ(intensity(w, 0, 0), 300 * 3.2);
  EXPECT_DOUBLE_EQ(*w.rated_lumens, 3200.0);
}

TEST(LdtParser, LampSetsAreReadInEitherOrder) {
  LdtSpec by_field;
  by_field.lamp_sets = 2;
  by_field.lamp_lines = {"1",   "2",   "T8", "T5", "1000", "2000",
                         "830", "840", "1A", "1B", "10",   "20"};
  LdtSpec by_set = by_field;
  by_set.lamp_lines = {"1", "T8", "1000", "830", "1A", "10", "2", "T5", "2000", "840", "1B", "20"};
  const auto a = parse_ldt(ldt_text(by_field), "field.ldt");
  const auto b = parse_ldt(ldt_text(by_set), "set.ldt");
  EXPECT_FALSE(a.lamp_sets_one_set_at_a_time);
  EXPECT_TRUE(b.lamp_sets_one_set_at_a_time);
  for (const auto* d : {&a, &b}) {
    ASSERT_EQ(d->lamp_sets.size(), 2u);
    EXPECT_EQ(d->lamp_sets[0].count, 1);
    EXPECT_EQ(d->lamp_sets[0].type, "T8");
    EXPECT_EQ(d->lamp_sets[1].flux_lm, 2000.0);
    EXPECT_EQ(d->lamp_sets[1].colour_rendering, "1B");
    EXPECT_EQ(d->lamp_sets[1].watts, 20.0);
    EXPECT_DOUBLE_EQ(ldt_candela_scale(*d), 1.0);  // the first set's 1000 lm
  }
}

TEST(LdtParser, AcceptsDecimalCommas) {
  LdtSpec s;
  s.values = {"12,5", "0,25"};
  const auto d = parse_ldt(ldt_text(s), "comma.ldt");
  EXPECT_EQ(d.intensities, (std::vector<double>{12.5, 0.25}));
}

TEST(LdtParser, LuminousAreaShapes) {
  LdtSpec s;
  s.luminous_length = "600";
  const auto round = ldt_luminous_opening(parse_ldt(ldt_text(s), "r.ldt"));
  EXPECT_EQ(round.shape, OpeningShape::kCircular);
  EXPECT_DOUBLE_EQ(round.width_m, 0.6);
  EXPECT_DOUBLE_EQ(round.length_m, 0.6);
  s.luminous_height = "40";
  EXPECT_EQ(ldt_luminous_opening(parse_ldt(ldt_text(s), "c.ldt")).shape,
            OpeningShape::kVerticalCylinder);
  s.luminous_width = "300";
  s.luminous_height = "0";
  const auto rect = ldt_luminous_opening(parse_ldt(ldt_text(s), "q.ldt"));
  EXPECT_EQ(rect.shape, OpeningShape::kRectangular);
  EXPECT_DOUBLE_EQ(rect.length_m, 0.6);
  EXPECT_DOUBLE_EQ(rect.width_m, 0.3);
  s.luminous_length = "0";
  s.luminous_width = "0";
  EXPECT_EQ(ldt_luminous_opening(parse_ldt(ldt_text(s), "p.ldt")).shape, OpeningShape::kPoint);
}

TEST(LdtParser, SmallValidFileLoads) {
  const auto w = load_ldt(test_data("small_axial.ldt"));
  EXPECT_DOUBLE_EQ(intensity(w, 0, radians(45)), 200.0);
  EXPECT_DOUBLE_EQ(*w.rated_lumens, 800.0);
  EXPECT_EQ(w.input_watts, 10.0);  // the first lamp set's wattage with ballast
}

TEST(LdtParser, TruncatedFileIsReportedAtItsLastLine) {
  expect_input_error([] { load_ldt(test_data("bad_truncated.ldt")); },
                     {"bad_truncated.ldt:48:", "end of file", "2 of 3"});
}

TEST(LdtParser, NonNumericValueIsReportedAtItsLine) {
  expect_input_error([] { load_ldt(test_data("bad_non_numeric.ldt")); },
                     {"bad_non_numeric.ldt:48:", "'2OO'"});
}

TEST(LdtParser, CountsThatDoNotMatchTheDataAreRejected) {
  expect_input_error([] { load_ldt(test_data("bad_wrong_counts.ldt")); },
                     {"bad_wrong_counts.ldt:50:", "do not match"});
}

TEST(LdtParser, OtherBadInputIsReportedWithItsLine) {
  expect_input_error([] { parse_ldt("\n\n", "empty.ldt"); }, {"empty.ldt:1:", "empty"});
  LdtSpec s = eight_planes(5, 1);
  expect_input_error([&] { parse_ldt(ldt_text(s), "isym.ldt"); }, {"isym.ldt:3:", "Isym"});
  s = eight_planes(4, 3);
  s.mc = 6;
  s.c = {0, 60, 120, 180, 240, 300};
  expect_input_error([&] { parse_ldt(ldt_text(s), "mc.ldt"); }, {"mc.ldt:4:", "divisible by 4"});
  s = eight_planes(2, 5);
  s.c = {0, 45, 90, 135, 170, 225, 270, 315};
  expect_input_error([&] { parse_ldt(ldt_text(s), "plane.ldt"); }, {"plane.ldt:47:", "180"});
  s = LdtSpec{};
  s.values = {"300", "-1"};
  expect_input_error([&] { parse_ldt(ldt_text(s), "neg.ldt"); }, {"neg.ldt:47:", "negative"});
  s = LdtSpec{};
  s.lamp_lines = {"1", "LED", "0", "3000K", "1A", "10"};
  expect_input_error([&] { parse_ldt(ldt_text(s), "flux.ldt"); }, {"flux.ldt:29:", "flux"});
  s = LdtSpec{};
  s.gamma = {0, 90, 45};
  s.values = {"1", "2", "3"};
  expect_input_error([&] { parse_ldt(ldt_text(s), "gamma.ldt"); }, {"gamma.ldt:46:", "ascend"});
  s = LdtSpec{};
  s.values = {"1", "inf"};
  expect_input_error([&] { parse_ldt(ldt_text(s), "inf.ldt"); }, {"inf.ldt:47:", "'inf'"});
  expect_input_error([] { load_ldt(test_data("no_such_file.ldt")); }, {"no_such_file.ldt"});
}

TEST(LdtParser, GarbageNeverCrashes) {
  const std::string text = ldt_text(eight_planes(3, 5));
  for (std::size_t n = 0; n < text.size(); n += 3) {
    try {
      (void)make_ldt_web(parse_ldt(text.substr(0, n), "cut.ldt"));
    } catch (const InputError&) {
    }
  }
}

TEST(LdtParser, RandomByteChangesNeverCrash) {
  // Deterministic mutations of a valid file: each result parses or fails with InputError.
  test::parse_random_mutations(ldt_text(eight_planes(3, 5)), [](const std::string& text) {
    (void)make_ldt_web(parse_ldt(text, "mutated.ldt"));
  });
}

}  // namespace
}  // namespace relight
