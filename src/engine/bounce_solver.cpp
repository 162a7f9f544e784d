// Jacobi iteration of E = E_d + G_vv · diag(ρ) · E for all basis columns at once
// (ARCHITECTURE §4.3; see bounce_solver.h). Eigen's sparse × dense product is
// single-threaded without OpenMP, so the product is split over rows with oneTBB: each
// output row is a sum of albedo-scaled irradiance rows (row-major, K contiguous floats, so
// the inner loop is a vectorised axpy), and the convergence norms are reduced in a fixed
// order (parallel_deterministic_reduce) so the bounce count never depends on scheduling.
#include "engine/bounce_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "common/progress.h"

namespace relight {

namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Gather = Eigen::SparseMatrix<float, Eigen::RowMajor>;

constexpr Eigen::Index kRowGrain = 64;

// Per column, over vertex rows: Σ (E(n+1) − E(n))² and Σ E(n+1)².
struct ColumnChange {
  std::vector<double> difference, norm;
};

ColumnChange add(ColumnChange a, const ColumnChange& b) {
  for (std::size_t k = 0; k < a.difference.size(); ++k) {
    a.difference[k] += b.difference[k];
    a.norm[k] += b.norm[k];
  }
  return a;
}

// gathered = G · reflected for every receiver row, where reflected = diag(ρ) · E(n) on
// vertex rows. Since E(n+1) = E_d + gathered on vertex rows, the change of E is the change
// of `gathered`, measured here before each row is overwritten.
ColumnChange gather_bounce(const Gather& g, const RowMatrix& reflected, const RowMatrix& direct,
                           RowMatrix& gathered) {
  const Eigen::Index columns = reflected.cols(), vertices = direct.rows();
  const ColumnChange zero{std::vector<double>(columns, 0.0), std::vector<double>(columns, 0.0)};
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<Eigen::Index>(0, g.rows(), kRowGrain), zero,
      [&](const tbb::blocked_range<Eigen::Index>& rows, ColumnChange change) {
        Eigen::RowVectorXf sum(columns);
        for (Eigen::Index i = rows.begin(); i != rows.end(); ++i) {
          sum.setZero();
          for (Gather::InnerIterator it(g, i); it; ++it) {
            sum.noalias() += it.value() * reflected.row(it.index());
          }
          if (i < vertices) {
            for (Eigen::Index k = 0; k < columns; ++k) {
              const double d = double{sum[k]} - gathered(i, k);
              const double e = double{direct(i, k)} + sum[k];
              change.difference[k] += d * d;
              change.norm[k] += e * e;
            }
          }
          gathered.row(i) = sum;
        }
        return change;
      },
      add);
}

double max_relative_change(const ColumnChange& change) {
  double worst = 0;
  for (std::size_t k = 0; k < change.norm.size(); ++k) {
    if (change.norm[k] > 0) {
      worst = std::max(worst, std::sqrt(change.difference[k] / change.norm[k]));
    }
  }
  return worst;
}

// reflected = diag(ρ) · (E_d + gathered) on vertex rows: E(n+1) times the albedo.
void reflect(const Eigen::VectorXf& albedo, const RowMatrix& direct, const RowMatrix& gathered,
             RowMatrix& reflected) {
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, direct.rows(), kRowGrain),
                    [&](const tbb::blocked_range<Eigen::Index>& rows) {
                      for (Eigen::Index j = rows.begin(); j != rows.end(); ++j) {
                        reflected.row(j) = albedo[j] * (direct.row(j) + gathered.row(j));
                      }
                    });
}

// Converts the row-major working matrix to the column-major result, in parallel.
Eigen::MatrixXf to_column_major(const RowMatrix& m) {
  Eigen::MatrixXf out(m.rows(), m.cols());
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, m.rows(), 256),
                    [&](const tbb::blocked_range<Eigen::Index>& rows) {
                      const Eigen::Index n = rows.end() - rows.begin();
                      out.middleRows(rows.begin(), n) = m.middleRows(rows.begin(), n);
                    });
  return out;
}

struct ChannelSolution {
  Eigen::MatrixXf indirect;
  int bounces = 0;
};

ChannelSolution solve_channel(const Gather& g, const Eigen::VectorXf& albedo,
                              const RowMatrix& direct, const BounceSettings& settings,
                              Progress& bar) {
  const Eigen::Index receivers = g.rows(), columns = direct.cols();
  ChannelSolution solution;
  if (settings.max_bounces <= 0 || columns == 0 || albedo.isZero(0)) {
    solution.indirect = Eigen::MatrixXf::Zero(receivers, columns);
    bar.advance(std::max(settings.max_bounces, 1));
    return solution;
  }
  RowMatrix reflected = albedo.asDiagonal() * direct;
  RowMatrix gathered = RowMatrix::Zero(receivers, columns);
  while (solution.bounces < settings.max_bounces) {
    const ColumnChange change = gather_bounce(g, reflected, direct, gathered);
    ++solution.bounces;
    bar.advance();
    if (max_relative_change(change) < settings.tolerance) break;
    if (solution.bounces < settings.max_bounces) reflect(albedo, direct, gathered, reflected);
  }
  bar.advance(settings.max_bounces - solution.bounces);
  solution.indirect = to_column_major(gathered);
  return solution;
}

void check_sizes(const GatherOperator& gather, const Receivers& receivers,
                 const Eigen::MatrixXf& direct) {
  const auto receiver_count = static_cast<Eigen::Index>(receivers.size());
  if (gather.matrix.rows() != receiver_count ||
      gather.matrix.cols() != static_cast<Eigen::Index>(receivers.vertex_count) ||
      receivers.albedo.size() != receivers.size()) {
    throw std::invalid_argument("bounce solver: gather operator and receivers disagree");
  }
  if (direct.rows() != receiver_count) {
    throw std::invalid_argument("bounce solver: direct irradiance needs one row per receiver");
  }
}

// The vertices' albedo, one vector per channel.
std::array<Eigen::VectorXf, 3> channel_albedo(const Receivers& receivers) {
  const auto vertex_count = static_cast<Eigen::Index>(receivers.vertex_count);
  std::array<Eigen::VectorXf, 3> albedo;
  for (int c = 0; c < 3; ++c) {
    albedo[c].resize(vertex_count);
    for (Eigen::Index v = 0; v < vertex_count; ++v) {
      const Rgb& a = receivers.albedo[v];
      albedo[c][v] = static_cast<float>(c == 0 ? a.r : (c == 1 ? a.g : a.b));
    }
  }
  return albedo;
}

}  // namespace

Eigen::MatrixXf solve_bounces_rgb(const GatherOperator& gather, const Receivers& receivers,
                                  const Eigen::MatrixXf& direct, const BounceSettings& settings) {
  check_sizes(gather, receivers, direct);
  if (direct.cols() != 3) throw std::invalid_argument("bounce solver: RGB needs three columns");
  const auto vertex_count = static_cast<Eigen::Index>(receivers.vertex_count);
  const RowMatrix direct_vertices = direct.topRows(vertex_count);
  const std::array<Eigen::VectorXf, 3> albedo = channel_albedo(receivers);
  Progress quiet("interreflection", 1, false);
  if (albedo[0] == albedo[1] && albedo[0] == albedo[2]) {
    return solve_channel(gather.matrix, albedo[0], direct_vertices, settings, quiet).indirect;
  }
  Eigen::MatrixXf out(direct.rows(), 3);
  for (int c = 0; c < 3; ++c) {
    const RowMatrix column = direct_vertices.col(c);
    out.col(c) = solve_channel(gather.matrix, albedo[c], column, settings, quiet).indirect.col(0);
  }
  return out;
}

BounceResult solve_bounces(const GatherOperator& gather, const Receivers& receivers,
                           const Eigen::MatrixXf& direct, const BounceSettings& settings,
                           bool progress) {
  const auto start = std::chrono::steady_clock::now();
  check_sizes(gather, receivers, direct);
  const RowMatrix direct_vertices =
      direct.topRows(static_cast<Eigen::Index>(receivers.vertex_count));

  BounceResult result;
  const std::array<Eigen::VectorXf, 3> albedo = channel_albedo(receivers);
  Progress bar("interreflection", 3 * static_cast<std::uint64_t>(std::max(settings.max_bounces, 1)),
               progress);
  for (int c = 0; c < 3; ++c) {
    bool copied = false;
    for (int earlier = 0; earlier < c && !copied; ++earlier) {
      if (albedo[earlier] == albedo[c]) {
        result.indirect[c] = result.indirect[earlier];
        copied = true;
      }
    }
    if (copied) {
      bar.advance(std::max(settings.max_bounces, 1));
      continue;
    }
    ChannelSolution solution =
        solve_channel(gather.matrix, albedo[c], direct_vertices, settings, bar);
    result.indirect[c] = std::move(solution.indirect);
    result.bounces = std::max(result.bounces, solution.bounces);
  }
  bar.finish();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relight
