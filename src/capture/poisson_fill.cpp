#include "capture/poisson_fill.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace relight {

void poisson_fill(int width, int height, std::span<Rgb> texels,
                  std::span<const std::uint8_t> hole) {
  const std::size_t count = static_cast<std::size_t>(width) * height;
  std::vector<int> unknown(count, -1);
  int n = 0;
  for (std::size_t t = 0; t < count; ++t) {
    if (hole[t]) unknown[t] = n++;
  }
  if (n == 0) return;
  if (static_cast<std::size_t>(n) == count) {
    throw std::invalid_argument("poisson_fill: the whole map is a hole");
  }
  const auto value_of = [&](std::size_t t, int c) {
    const Rgb& v = texels[t];
    return c == 0 ? v.r : c == 1 ? v.g : v.b;
  };
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * width + i;
      const int row = unknown[t];
      if (row < 0) continue;
      const std::size_t neighbours[4] = {
          static_cast<std::size_t>(j) * width + (i + 1) % width,
          static_cast<std::size_t>(j) * width + (i + width - 1) % width, j > 0 ? t - width : count,
          j + 1 < height ? t + width : count};
      double degree = 0;
      for (const std::size_t m : neighbours) {
        if (m == count) continue;
        degree += 1;
        if (unknown[m] >= 0) {
          entries.emplace_back(row, unknown[m], -1.0);
        } else {
          for (int c = 0; c < 3; ++c) rhs(row, c) += value_of(m, c);
        }
      }
      entries.emplace_back(row, row, degree);
    }
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  // A hole component that touches no known texel would make the matrix singular; the
  // diagonal's tiny extra keeps it solvable (such a component fills with 0).
  for (int k = 0; k < n; ++k) laplacian.coeffRef(k, k) += 1e-9;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("poisson_fill: factorisation failed");
  const Eigen::MatrixXd fill = solver.solve(rhs);
  for (std::size_t t = 0; t < count; ++t) {
    if (unknown[t] < 0) continue;
    const int row = unknown[t];
    texels[t] = {std::max(fill(row, 0), 0.0), std::max(fill(row, 1), 0.0),
                 std::max(fill(row, 2), 0.0)};
  }
}

}  // namespace relight
