// run_child (common/child_process.h): standard output kept, standard error handed over line by
// line, exit codes and signals reported, a cancelled program ended, a missing one refused.
#include "common/child_process.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

namespace relight {
namespace {

TEST(ChildProcess, KeepsStandardOutputAndSplitsStandardErrorIntoLines) {
  std::vector<std::string> lines;
  ChildOptions options;
  options.on_error_line = [&](const std::string& line) { lines.push_back(line); };
  const ChildResult r = run_child(
      {"sh", "-c", "printf 'one\\ntwo'; printf 'a 10%%\\nb 20%%\\nlast' >&2; exit 3"}, options);
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.out, "one\ntwo");
  EXPECT_EQ(lines, (std::vector<std::string>{"a 10%", "b 20%", "last"}));
  EXPECT_EQ(r.err_end, "a 10%\nb 20%\nlast");
  EXPECT_EQ(last_line(r.err_end), "last");
}

TEST(ChildProcess, StandardInputIsEmpty) {
  const ChildResult r = run_child({"cat"});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "");
}

TEST(ChildProcess, KeepsOnlyTheEndOfALongStandardError) {
  const ChildResult r =
      run_child({"sh", "-c", "head -c 300000 /dev/zero | tr '\\0' x >&2; echo ' end' >&2"});
  EXPECT_EQ(r.status, 0);
  EXPECT_LE(r.err_end.size(), std::size_t{64} << 10);
  EXPECT_EQ(last_line(r.err_end).substr(last_line(r.err_end).size() - 4), " end");
}

TEST(ChildProcess, ACancelledProgramEndsWithinASecond) {
  const auto start = std::chrono::steady_clock::now();
  ChildOptions options;
  options.cancelled = [&] {
    return std::chrono::steady_clock::now() - start > std::chrono::milliseconds(100);
  };
  const ChildResult r = run_child({"sleep", "30"}, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 128 + 15);  // SIGTERM
  EXPECT_LT(seconds, 1.0);
}

TEST(ChildProcess, AMissingProgramIsRefusedWithItsName) {
  try {
    (void)run_child({"relight-no-such-program"});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot run relight-no-such-program"), std::string::npos);
  }
}

TEST(ChildProcess, LastLineSkipsTrailingBlankLines) {
  EXPECT_EQ(last_line("first\n  error: x: y  \n\n \n"), "error: x: y");
  EXPECT_EQ(last_line(""), "");
  EXPECT_EQ(last_line("only"), "only");
}

}  // namespace
}  // namespace relight
