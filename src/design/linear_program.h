// A linear program and its exact solution: minimise c·x subject to row_lo ≤ A x ≤ row_hi and
// col_lo ≤ x ≤ col_hi, by COIN-OR CLP (Debian coinor-libclp-dev; initialSolve: presolve, then
// the dual simplex). CLP rather
// than GLPK: both are well-kept Debian packages and solve these small dense programs (tens of
// columns, thousands of rows) in milliseconds; CLP's licence (EPL-2.0) asks nothing of the
// programs that link it, and its dual simplex restarts cheaply when only bounds change.
// The only file that includes CLP. Tests: tests/design/linear_program_test.cpp.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace relight {

inline constexpr double kLpInfinity = std::numeric_limits<double>::infinity();

struct LinearProgram {
  std::size_t cols = 0;
  std::vector<double> c, col_lo, col_hi;  // cols each
  std::vector<double> a;                  // rows × cols, row-major (zeros skipped)
  std::vector<double> row_lo, row_hi;     // rows each; ±kLpInfinity for none

  std::size_t rows() const { return row_lo.size(); }
  // Appends a row lo ≤ coefficients · x ≤ hi (coefficients.size() == cols).
  void add_row(const std::vector<double>& coefficients, double lo, double hi);
};

enum class LpStatus { kOptimal, kInfeasible, kFailed };

struct LpSolution {
  LpStatus status = LpStatus::kFailed;
  std::vector<double> x;  // cols, when optimal
  double objective = 0;
  int iterations = 0;  // simplex iterations
};

LpSolution solve_linear_program(const LinearProgram& lp);

}  // namespace relight
