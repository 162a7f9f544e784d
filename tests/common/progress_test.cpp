// Progress (common/progress.h): what it prints in a log, read back by parse_progress_line.
#include "common/progress.h"

#include <gtest/gtest.h>

#include <sstream>

namespace relight {
namespace {

TEST(Progress, ALogsLinesReadBackAsLabelAndFractionToATenth) {
  testing::internal::CaptureStderr();
  {
    Progress progress("direct light", 20);
    for (int k = 0; k < 20; ++k) progress.advance();
  }
  std::istringstream log(testing::internal::GetCapturedStderr());
  std::vector<double> fractions;
  for (std::string line; std::getline(log, line);) {
    const std::optional<ProgressLine> p = parse_progress_line(line);
    ASSERT_TRUE(p.has_value()) << line;
    EXPECT_EQ(p->label, "direct light");
    fractions.push_back(p->fraction);
  }
  ASSERT_GE(fractions.size(), 10U);  // every 10% and the start
  EXPECT_DOUBLE_EQ(fractions.front(), 0.0);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  for (std::size_t k = 1; k < fractions.size(); ++k) EXPECT_GE(fractions[k], fractions[k - 1]);
}

TEST(Progress, OtherLinesAreNotProgress) {
  EXPECT_FALSE(parse_progress_line("warning: 12 faces turned").has_value());
  EXPECT_FALSE(parse_progress_line("a [b] 10% 1s").has_value());
  EXPECT_FALSE(parse_progress_line("bounce [###] x%").has_value());
  EXPECT_FALSE(parse_progress_line("bounce [###...] 140.0% 1.0s").has_value());
  const std::optional<ProgressLine> p = parse_progress_line("bounce 2   [###...] 50.0%    3.1s");
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->label, "bounce 2");
  EXPECT_DOUBLE_EQ(p->fraction, 0.5);
}

}  // namespace
}  // namespace relight
