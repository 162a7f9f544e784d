#include "design/linear_program.h"

#include <cmath>
#include <stdexcept>

#include <ClpSimplex.hpp>

namespace relight {

namespace {

double clp_bound(double v) {
  if (v == kLpInfinity) return COIN_DBL_MAX;
  if (v == -kLpInfinity) return -COIN_DBL_MAX;
  return v;
}

std::vector<double> clp_bounds(const std::vector<double>& v) {
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = clp_bound(v[i]);
  return out;
}

}  // namespace

void LinearProgram::add_row(const std::vector<double>& coefficients, double lo, double hi) {
  if (coefficients.size() != cols) throw std::logic_error("add_row: wrong number of coefficients");
  a.insert(a.end(), coefficients.begin(), coefficients.end());
  row_lo.push_back(lo);
  row_hi.push_back(hi);
}

LpSolution solve_linear_program(const LinearProgram& lp) {
  const std::size_t rows = lp.rows();
  if (lp.c.size() != lp.cols || lp.col_lo.size() != lp.cols || lp.col_hi.size() != lp.cols ||
      lp.a.size() != rows * lp.cols || lp.row_hi.size() != rows) {
    throw std::logic_error("solve_linear_program: inconsistent sizes");
  }
  // Column-ordered sparse copy of the row-major matrix, zeros left out.
  std::vector<CoinBigIndex> start(lp.cols + 1, 0);
  std::vector<int> index;
  std::vector<double> value;
  index.reserve(lp.a.size());
  value.reserve(lp.a.size());
  for (std::size_t j = 0; j < lp.cols; ++j) {
    for (std::size_t i = 0; i < rows; ++i) {
      const double v = lp.a[i * lp.cols + j];
      if (v != 0) {
        index.push_back(static_cast<int>(i));
        value.push_back(v);
      }
    }
    start[j + 1] = static_cast<CoinBigIndex>(index.size());
  }
  const std::vector<double> col_lo = clp_bounds(lp.col_lo), col_hi = clp_bounds(lp.col_hi);
  const std::vector<double> row_lo = clp_bounds(lp.row_lo), row_hi = clp_bounds(lp.row_hi);

  ClpSimplex model;
  model.setLogLevel(0);
  model.loadProblem(static_cast<int>(lp.cols), static_cast<int>(rows), start.data(), index.data(),
                    value.data(), col_lo.data(), col_hi.data(), lp.c.data(), row_lo.data(),
                    row_hi.data());
  model.scaling(3);  // geometric then equilibrium: the rows' lux span several decades
  model.initialSolve();

  LpSolution out;
  out.iterations = model.numberIterations();
  if (model.isProvenOptimal()) {
    out.status = LpStatus::kOptimal;
    const double* x = model.primalColumnSolution();
    out.x.assign(x, x + lp.cols);
    out.objective = model.objectiveValue();
  } else if (model.isProvenPrimalInfeasible()) {
    out.status = LpStatus::kInfeasible;
  }
  return out;
}

}  // namespace relight
