// IES LM-63 parsing: versions, scaling, every type-C symmetry, tilt, units, and bad input
// reported as "FILE:LINE: reason".
#include "light/ies_parser.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "light/distribution.h"
#include "photometry_test_support.h"

namespace relight {
namespace {

using test::expect_input_error;
using test::test_data;

// An IES text with the given photometric block after TILT=NONE.
std::string ies(const std::string& body, const std::string& version = "IESNA:LM-63-2002") {
  return version + "\n[TEST] unit test\n[MANUFAC] relight\nTILT=NONE\n" + body;
}

std::size_t index_of(const std::vector<double>& v, double x) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::abs(v[i] - x) < 1e-9) return i;
  }
  ADD_FAILURE() << "angle " << x << " missing";
  return 0;
}

double web_value(const PhotometricWeb& w, double c, double g) {
  return w.at(index_of(w.c_deg, c), index_of(w.gamma_deg, g));
}

TEST(IesParser, ReadsHeaderKeywordsAndMoreLines) {
  const auto d = parse_ies(
      "IESNA:LM-63-2002\n[TEST] R1\n[LUMINAIRE] Line one\n[MORE] line two\nTILT=NONE\n"
      "1 1000 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5\n",
      "k.ies");
  EXPECT_EQ(d.version, IesVersion::kLm63_2002);
  ASSERT_EQ(d.keywords.size(), 2u);
  EXPECT_EQ(d.keywords[1].name, "LUMINAIRE");
  EXPECT_EQ(d.keywords[1].value, "Line one\nline two");
}

TEST(IesParser, ScalesCandelaByMultiplierAndBallastFactor) {
  const auto d =
      parse_ies(ies("1 1000 2 3 1 1 2 0 0 0\n0.75 1 10\n0 45 90\n0\n100 80 0\n"), "s.ies");
  EXPECT_DOUBLE_EQ(ies_candela_scale(d), 1.5);
  const auto w = make_ies_web(d);
  EXPECT_DOUBLE_EQ(web_value(w, 0, 0), 150.0);
  EXPECT_DOUBLE_EQ(web_value(w, 0, 45), 120.0);
}

TEST(IesParser, NeverAppliesThe2019FileGenerationType) {
  const auto d = parse_ies(
      ies("1 1000 1 2 1 1 2 0 0 0\n1 1.10000 10\n0 90\n0\n100 0\n", "IES:LM-63-2019"), "g.ies");
  EXPECT_EQ(d.version, IesVersion::kLm63_2019);
  EXPECT_DOUBLE_EQ(d.ballast_lamp_factor, 1.1);
  EXPECT_DOUBLE_EQ(ies_candela_scale(d), 1.0);
}

TEST(IesParser, Applies1995BallastLampPhotometricFactor) {
  const auto d = parse_ies(
      ies("1 1000 1 2 1 1 2 0 0 0\n0.9 0.95 10\n0 90\n0\n100 0\n", "IESNA:LM-63-1995"), "f.ies");
  EXPECT_DOUBLE_EQ(ies_candela_scale(d), 0.9 * 0.95);
}

TEST(IesParser, RelativePhotometryRatesLampsTimesLumensPerLamp) {
  const auto w =
      make_ies_web(parse_ies(ies("3 1200 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5\n"), "r.ies"));
  ASSERT_TRUE(w.rated_lumens);
  EXPECT_DOUBLE_EQ(*w.rated_lumens, 3600.0);
  EXPECT_FALSE(w.absolute_photometry);
}

TEST(IesParser, AbsolutePhotometryHasNoRatedLumens) {
  const auto w =
      make_ies_web(parse_ies(ies("1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n10 5\n"), "a.ies"));
  EXPECT_FALSE(w.rated_lumens);
  EXPECT_TRUE(w.absolute_photometry);
}

TEST(IesParser, QuadrantSymmetryFromLastHorizontalAngle90) {
  const auto d =
      parse_ies(ies("1 -1 1 2 3 1 2 0 0 0\n1 1 10\n0 90\n0 45 90\n1 2 3 4 5 6\n"), "q.ies");
  EXPECT_EQ(d.symmetry, CSymmetry::kQuadrant);
  const auto w = make_ies_web(d);
  EXPECT_EQ(web_value(w, 45, 90), 4.0);
  EXPECT_EQ(web_value(w, 135, 90), 4.0);
  EXPECT_EQ(web_value(w, 225, 90), 4.0);
  EXPECT_EQ(web_value(w, 315, 90), 4.0);
  EXPECT_EQ(web_value(w, 270, 0), 5.0);
}

TEST(IesParser, BilateralSymmetryFromLastHorizontalAngle180) {
  const auto d =
      parse_ies(ies("1 -1 1 2 3 1 2 0 0 0\n1 1 10\n0 90\n0 90 180\n1 2 3 4 5 6\n"), "b.ies");
  EXPECT_EQ(d.symmetry, CSymmetry::kBilateralC0C180);
  const auto w = make_ies_web(d);
  EXPECT_EQ(web_value(w, 270, 0), 3.0);
  EXPECT_EQ(web_value(w, 360, 90), 2.0);
}

TEST(IesParser, FilesRunning90To270AreMirroredAboutTheC90Plane) {
  const auto w = load_ies(test_data("bilateral_90_270_2019.ies"));
  // Stored H90 (10 20 5), H180 (30 40 6), H270 (50 60 7), × multiplier 2 × ballast 0.8.
  EXPECT_DOUBLE_EQ(web_value(w, 0, 90), 40 * 1.6);  // I(0) = I(180)
  EXPECT_DOUBLE_EQ(web_value(w, 90, 0), 10 * 1.6);
  EXPECT_DOUBLE_EQ(web_value(w, 270, 180), 7 * 1.6);
  EXPECT_DOUBLE_EQ(intensity(w, radians(45), radians(90)), intensity(w, radians(135), radians(90)));
  EXPECT_DOUBLE_EQ(intensity(w, radians(300), radians(45)),
                   intensity(w, radians(240), radians(45)));
  EXPECT_DOUBLE_EQ(*w.rated_lumens, 3000.0);
  EXPECT_EQ(w.input_watts, 25.0);  // the input watts after the ballast factors
  EXPECT_EQ(w.opening.shape, OpeningShape::kCircular);
  EXPECT_DOUBLE_EQ(w.opening.width_m, 0.3048);  // 1 ft
}

TEST(IesParser, NoSymmetryWhenLastHorizontalAngleExceeds180) {
  const auto d = parse_ies(
      ies("1 -1 1 2 4 1 2 0 0 0\n1 1 10\n0 90\n0 90 180 270\n1 2 3 4 5 6 7 8\n"), "n.ies");
  EXPECT_EQ(d.symmetry, CSymmetry::kNone);
  const auto w = make_ies_web(d);
  EXPECT_EQ(w.c_deg.back(), 360.0);
  EXPECT_EQ(web_value(w, 360, 0), 1.0);
  EXPECT_EQ(web_value(w, 270, 90), 8.0);
}

TEST(IesParser, AxialSymmetryFromOneHorizontalAngle) {
  const auto d = parse_ies(ies("1 -1 1 3 1 1 2 0 0 0\n1 1 10\n0 60 90\n0\n9 6 3\n"), "x.ies");
  EXPECT_EQ(d.symmetry, CSymmetry::kAxial);
  EXPECT_TRUE(is_axisymmetric(make_ies_web(d)));
}

TEST(IesParser, UpperHemisphereGridIsZeroBelow90) {
  const auto w =
      make_ies_web(parse_ies(ies("1 -1 1 3 1 1 2 0 0 0\n1 1 10\n90 135 180\n0\n3 6 9\n"), "u.ies"));
  EXPECT_EQ(intensity(w, 0, radians(45)), 0.0);
  EXPECT_DOUBLE_EQ(intensity(w, 0, radians(157.5)), 7.5);
}

TEST(IesParser, ValuesMaySpanLinesAndUseCommas) {
  const auto w = make_ies_web(
      parse_ies(ies("1,-1\n1 3\n1,1 2,0,0\n0 1 1\n10 0,\n45\n90 0 15,\n 10 5\n"), "c.ies"));
  EXPECT_DOUBLE_EQ(web_value(w, 0, 45), 10.0);
  EXPECT_DOUBLE_EQ(web_value(w, 0, 90), 5.0);
}

TEST(IesParser, AcceptsCrLfLineEndings) {
  const auto d = parse_ies(
      "IESNA:LM-63-1995\r\n[TEST] crlf\r\nTILT=NONE\r\n1 -1 1 2 1 1 2 0 0 0\r\n1 1 10\r\n0 "
      "90\r\n0\r\n7 3\r\n",
      "crlf.ies");
  EXPECT_EQ(d.candela, (std::vector<double>{7, 3}));
}

TEST(IesParser, FeetAreConvertedToMetres) {
  const auto w =
      make_ies_web(parse_ies(ies("1 -1 1 2 1 1 1 2 4 0\n1 1 10\n0 90\n0\n1 0\n"), "ft.ies"));
  EXPECT_EQ(w.opening.shape, OpeningShape::kRectangular);
  EXPECT_DOUBLE_EQ(w.opening.width_m, 2 * 0.3048);
  EXPECT_DOUBLE_EQ(w.opening.length_m, 4 * 0.3048);
}

TEST(IesParser, TiltIncludeIsParsedAndKeptUnapplied) {
  const auto w = load_ies(test_data("tilt_include.ies"));
  ASSERT_TRUE(w.tilt);
  EXPECT_EQ(w.tilt->lamp_to_luminaire_geometry, 1);
  EXPECT_EQ(w.tilt->angles_deg, (std::vector<double>{0, 30, 60, 90}));
  EXPECT_EQ(w.tilt->factors, (std::vector<double>{1.0, 0.95, 0.85, 0.7}));
  EXPECT_DOUBLE_EQ(tilt_factor(*w.tilt, 45), 0.9);
  EXPECT_DOUBLE_EQ(intensity(w, 0, 0), 100.0);  // candela as measured
}

TEST(IesParser, TiltFileIsReadFromBesideTheIesFile) {
  const auto w = load_ies(test_data("tilt_file.ies"));
  ASSERT_TRUE(w.tilt);
  EXPECT_EQ(w.tilt->lamp_to_luminaire_geometry, 2);
  EXPECT_EQ(w.tilt->factors, (std::vector<double>{1, 0.9, 0.8}));
}

TEST(IesParser, MissingTiltFileIsReportedAtTheTiltLine) {
  expect_input_error([] { load_ies(test_data("tilt_file_missing.ies")); },
                     {"tilt_file_missing.ies:4:", "no_such_table.tlt"});
}

TEST(IesParser, RejectsPhotometricTypesBAndA) {
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 1 2 2 0 0 0\n1 1 10\n-90 90\n0\n1 1\n"), "typeb.ies"); },
      {"typeb.ies:5:", "type B", "not supported"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 1 3 2 0 0 0\n1 1 10\n-90 90\n0\n1 1\n"), "typea.ies"); },
      {"typea.ies:5:", "type A"});
}

TEST(IesParser, TruncatedFileIsReportedAtItsLastLine) {
  expect_input_error([] { load_ies(test_data("bad_truncated.ies")); },
                     {"bad_truncated.ies:10:", "end of file", "6 candela values, found 5"});
}

TEST(IesParser, NonNumericValueIsReportedAtItsLine) {
  expect_input_error([] { load_ies(test_data("bad_non_numeric.ies")); },
                     {"bad_non_numeric.ies:9:", "'8O'"});
}

TEST(IesParser, NanValueIsRejected) {
  expect_input_error([] { load_ies(test_data("bad_nan.ies")); }, {"bad_nan.ies:10:", "'nan'"});
}

TEST(IesParser, CountsThatDoNotMatchTheDataAreRejected) {
  expect_input_error([] { load_ies(test_data("bad_wrong_counts.ies")); },
                     {"bad_wrong_counts.ies:9:", "counts do not match"});
}

TEST(IesParser, NegativeAngleCountIsRejected) {
  expect_input_error([] { load_ies(test_data("bad_negative_count.ies")); },
                     {"bad_negative_count.ies:5:", "vertical angles", "-3"});
}

TEST(IesParser, OtherBadInputIsReportedWithItsLine) {
  expect_input_error([] { parse_ies("", "empty.ies"); }, {"empty.ies:1:", "empty"});
  expect_input_error([] { parse_ies("IESNA:LM-63-2002\n[TEST] x\n1 2 3\n", "notilt.ies"); },
                     {"notilt.ies:3:", "TILT"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 2 1 2 0 0 0\n1 1 10\n0 90\n90 0\n1 1 1 1\n"), "order.ies"); },
      {"order.ies:8:", "ascend"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 2 1 2 0 0 0\n1 1 10\n0 90\n0 120\n1 1 1 1\n"), "sym.ies"); },
      {"sym.ies:8:", "symmetry"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 200\n0\n1 1\n"), "range.ies"); },
      {"range.ies:7:", "[0, 180]"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n1\n-2\n"), "neg.ies"); },
      {"neg.ies:10:", "negative candela"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 0 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n1 1\n"), "mult.ies"); },
      {"mult.ies:5:", "multiplier"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n1 1e999\n"), "huge.ies"); },
      {"huge.ies:9:", "'1e999'"});
  expect_input_error(
      [] { parse_ies(ies("1 -1 1 2.5 1 1 2 0 0 0\n1 1 10\n0 90\n0\n1 1\n"), "frac.ies"); },
      {"frac.ies:5:", "integer"});
  expect_input_error([] { load_ies(test_data("no_such_file.ies")); }, {"no_such_file.ies"});
}

TEST(IesParser, GarbageNeverCrashes) {
  // Cut a valid file at every byte: each prefix parses or fails with InputError.
  const std::string text =
      ies("1 1000 1 3 2 1 2 -0.1 0.2 0\n1 1 10\n0 45 90\n0 180\n100 80 0\n100 80 0\n");
  for (std::size_t n = 0; n < text.size(); ++n) {
    try {
      (void)make_ies_web(parse_ies(text.substr(0, n), "cut.ies"));
    } catch (const InputError&) {
    }
  }
}

TEST(IesParser, RandomByteChangesNeverCrash) {
  // Deterministic mutations of a valid file: each result parses or fails with InputError.
  test::parse_random_mutations(
      ies("1 1000 1 3 2 1 2 -0.1 0.2 0\n1 1 10\n0 45 90\n0 180\n100 80 0\n100 80 0\n"),
      [](const std::string& text) { (void)make_ies_web(parse_ies(text, "mutated.ies")); });
}

}  // namespace
}  // namespace relight
