// The CLP wrapper (design/linear_program.h) on programs solved by hand.
#include <gtest/gtest.h>

#include "design/linear_program.h"

namespace relight {
namespace {

// min x + y s.t. x + 2y ≥ 2, 3x + y ≥ 3, 0 ≤ x, y ≤ 10: the corner x = 0.8, y = 0.6.
LinearProgram two_corners() {
  LinearProgram lp;
  lp.cols = 2;
  lp.c = {1, 1};
  lp.col_lo = {0, 0};
  lp.col_hi = {10, 10};
  lp.add_row({1, 2}, 2, kLpInfinity);
  lp.add_row({3, 1}, 3, kLpInfinity);
  return lp;
}

TEST(LinearProgram, FindsTheOptimalCornerWithin1e9) {
  const LpSolution s = solve_linear_program(two_corners());
  ASSERT_EQ(s.status, LpStatus::kOptimal);
  EXPECT_NEAR(s.x[0], 0.8, 1e-9);
  EXPECT_NEAR(s.x[1], 0.6, 1e-9);
  EXPECT_NEAR(s.objective, 1.4, 1e-9);
  EXPECT_GT(s.iterations, 0);
}

TEST(LinearProgram, AnUpperBoundRowAndColumnBoundsHold) {
  LinearProgram lp = two_corners();
  lp.c = {-1, -1};  // maximise x + y
  lp.add_row({1, 1}, -kLpInfinity, 5);
  lp.col_hi = {3, 10};
  const LpSolution s = solve_linear_program(lp);
  ASSERT_EQ(s.status, LpStatus::kOptimal);
  EXPECT_NEAR(s.objective, -5, 1e-9);
  EXPECT_LE(s.x[0], 3 + 1e-9);
  EXPECT_NEAR(s.x[0] + s.x[1], 5, 1e-9);
}

TEST(LinearProgram, ContradictoryRowsAreInfeasible) {
  LinearProgram lp = two_corners();
  lp.add_row({1, 1}, -kLpInfinity, 1);  // x + y ≤ 1 while the cheapest meeting both rows is 1.4
  EXPECT_EQ(solve_linear_program(lp).status, LpStatus::kInfeasible);
}

TEST(LinearProgram, InconsistentSizesAreAProgrammingError) {
  LinearProgram lp = two_corners();
  lp.c = {1};
  EXPECT_THROW(solve_linear_program(lp), std::logic_error);
  EXPECT_THROW(lp.add_row({1, 2, 3}, 0, 1), std::logic_error);
}

}  // namespace
}  // namespace relight
