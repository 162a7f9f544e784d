// Jacobi iteration of E = E_d + G_vv · diag(ρ) · E for all basis columns at once (see
// bounce_solver.h). Eigen's sparse × dense product is single-threaded without OpenMP, so the
// product is split over rows with oneTBB: each output row is a sum of albedo-scaled irradiance rows
// (row-major, K contiguous floats, so the inner loop is a vectorised axpy), and the convergence
// norms are reduced in a fixed order (parallel_deterministic_reduce) so the bounce count never
// depends on scheduling.
#include "engine/bounce_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
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

}  // namespace

void gather_rgb_row(const Eigen::SparseMatrix<float, Eigen::RowMajor>& gather, Eigen::Index row,
                    std::span<const float> reflected, float (&sum)[3]) {
  // Raw arrays rather than Eigen's iterator: two independent sums per channel let the loads
  // of the next entry overlap the adds of this one.
  const auto* columns = gather.innerIndexPtr();
  const float* values = gather.valuePtr();
  const auto begin = gather.outerIndexPtr()[row];
  const auto end = gather.isCompressed() ? gather.outerIndexPtr()[row + 1]
                                         : begin + gather.innerNonZeroPtr()[row];
  const float* light = reflected.data();
  float a0 = 0, a1 = 0, a2 = 0, b0 = 0, b1 = 0, b2 = 0;
  auto i = begin;
  for (; i + 1 < end; i += 2) {
    const float* l = light + 3 * static_cast<std::size_t>(columns[i]);
    const float* m = light + 3 * static_cast<std::size_t>(columns[i + 1]);
    const float v = values[i], w = values[i + 1];
    a0 += v * l[0];
    a1 += v * l[1];
    a2 += v * l[2];
    b0 += w * m[0];
    b1 += w * m[1];
    b2 += w * m[2];
  }
  if (i < end) {
    const float* l = light + 3 * static_cast<std::size_t>(columns[i]);
    a0 += values[i] * l[0];
    a1 += values[i] * l[1];
    a2 += values[i] * l[2];
  }
  sum[0] = a0 + b0;
  sum[1] = a1 + b1;
  sum[2] = a2 + b2;
}

namespace {

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

// sum[0, columns) = Σ over the entries of one row of G of value · reflected[index][0, columns)
// (row-major, `columns` floats a row): the inner loop of a bounce, an axpy per entry. Compiled
// twice, for the x86-64 baseline (SSE2) and for x86-64-v3 (AVX2 and FMA: eight floats a step), the
// one the CPU runs chosen when the program loads: the loop is bound by reading the rows of
// `reflected`, and AVX2 reads them faster, while column tiles that stay in a core's cache, reading
// G once per tile, are slower (measured: docs/decisions.md). Not under ThreadSanitizer: the clones'
// ifunc resolver runs in the dynamic loader before TSan's runtime is up, and TSan instruments it (a
// crash at load; the TSan build of make test-sanitize, where speed does not matter).
#ifndef __SANITIZE_THREAD__
__attribute__((target_clones("default", "arch=x86-64-v3")))
#endif
void gather_columns(
    const float* values, const int* indices, Eigen::Index entries, const float* reflected,
    Eigen::Index columns, float* __restrict sum) {
  std::fill_n(sum, columns, 0.0f);
  Eigen::Index e = 0;
  for (; e + 4 <= entries; e += 4) {
    const float a0 = values[e], a1 = values[e + 1], a2 = values[e + 2], a3 = values[e + 3];
    const float* __restrict r0 = reflected + indices[e] * columns;
    const float* __restrict r1 = reflected + indices[e + 1] * columns;
    const float* __restrict r2 = reflected + indices[e + 2] * columns;
    const float* __restrict r3 = reflected + indices[e + 3] * columns;
    for (Eigen::Index k = 0; k < columns; ++k) {
      sum[k] += (a0 * r0[k] + a1 * r1[k]) + (a2 * r2[k] + a3 * r3[k]);
    }
  }
  for (; e < entries; ++e) {
    const float a = values[e];
    const float* __restrict row = reflected + indices[e] * columns;
    for (Eigen::Index k = 0; k < columns; ++k) sum[k] += a * row[k];
  }
}

// gathered = G · reflected for every receiver row, where reflected = diag(ρ) · E(n) on
// vertex rows. Since E(n+1) = E_d + gathered on vertex rows, the change of E is the change
// of `gathered`, measured here before each row is overwritten. With `ranks` (engine/ranks.h),
// only this rank's rows, `gathered` and `direct` holding them as its local rows.
ColumnChange gather_bounce(const Gather& g, const RowMatrix& reflected, const RowMatrix& direct,
                           RowMatrix& gathered, const RankShares* ranks) {
  const Eigen::Index columns = reflected.cols();
  const ColumnChange zero{std::vector<double>(columns, 0.0), std::vector<double>(columns, 0.0)};
  // Rows [begin, end) of G into local rows from `local`.
  const auto gather_rows = [&](Eigen::Index begin, Eigen::Index end, Eigen::Index local,
                               ColumnChange& change) {
    Eigen::RowVectorXf sum(columns);
    for (Eigen::Index i = begin; i != end; ++i, ++local) {
      const Eigen::Index first = g.outerIndexPtr()[i], last = g.outerIndexPtr()[i + 1];
      gather_columns(g.valuePtr() + first, g.innerIndexPtr() + first, last - first,
                     reflected.data(), columns, sum.data());
      if (local < direct.rows()) {
        for (Eigen::Index k = 0; k < columns; ++k) {
          const double d = double{sum[k]} - gathered(local, k);
          const double e = double{direct(local, k)} + sum[k];
          change.difference[k] += d * d;
          change.norm[k] += e * e;
        }
      }
      gathered.row(local) = sum;
    }
  };
  if (ranks == nullptr) {
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<Eigen::Index>(0, g.rows(), kRowGrain), zero,
        [&](const tbb::blocked_range<Eigen::Index>& rows, ColumnChange change) {
          gather_rows(rows.begin(), rows.end(), rows.begin(), change);
          return change;
        },
        add);
  }
  const std::vector<std::size_t> blocks = ranks->my_blocks();
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, blocks.size(), 1), zero,
      [&](const tbb::blocked_range<std::size_t>& range, ColumnChange change) {
        for (std::size_t b = range.begin(); b != range.end(); ++b) {
          const std::size_t first = ranks->first(blocks[b]);
          gather_rows(static_cast<Eigen::Index>(first),
                      static_cast<Eigen::Index>(ranks->last(blocks[b])),
                      static_cast<Eigen::Index>(ranks->local_row(first)), change);
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

// The change summed over the ranks, in rank order.
void sum_change(const RankShares& ranks, ColumnChange& change) {
  std::vector<double> mine = change.difference;
  mine.insert(mine.end(), change.norm.begin(), change.norm.end());
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(mine.data());
  const std::vector<std::vector<std::uint8_t>> all =
      ranks.exchange->all_gather({bytes, mine.size() * sizeof(double)});
  const std::size_t columns = change.norm.size();
  std::fill(change.difference.begin(), change.difference.end(), 0.0);
  std::fill(change.norm.begin(), change.norm.end(), 0.0);
  for (const std::vector<std::uint8_t>& theirs : all) {
    if (theirs.size() != mine.size() * sizeof(double)) {
      throw std::runtime_error("bounce solver: a rank's change of another size");
    }
    std::vector<double> v(mine.size());
    std::memcpy(v.data(), theirs.data(), theirs.size());
    for (std::size_t k = 0; k < columns; ++k) {
      change.difference[k] += v[k];
      change.norm[k] += v[columns + k];
    }
  }
}

// Several ranks: the vertex rows whose reflected light crosses between ranks each bounce. A rank's
// rows of G read the light of the vertices their rays hit, most of them in other ranks' blocks;
// only those rows are sent, each to the ranks that read it, and sensor rows (which reflect nothing)
// never are.
struct BounceHalo {
  std::vector<std::vector<std::uint32_t>> send;     // per rank: this rank's vertex rows it reads
  std::vector<std::vector<std::uint32_t>> receive;  // per rank: its vertex rows this rank reads
};

// Collective: every rank learns which of its vertex rows each other rank reads.
BounceHalo bounce_halo(const Gather& g, const RankShares& ranks, Eigen::Index vertices) {
  std::vector<char> read(static_cast<std::size_t>(vertices), 0);
  for (const std::size_t b : ranks.my_blocks()) {
    for (std::size_t r = ranks.first(b); r < ranks.last(b); ++r) {
      for (Gather::InnerIterator it(g, static_cast<Eigen::Index>(r)); it; ++it) {
        read[static_cast<std::size_t>(it.index())] = 1;
      }
    }
  }
  const auto n = static_cast<std::size_t>(ranks.size());
  BounceHalo halo{std::vector<std::vector<std::uint32_t>>(n),
                  std::vector<std::vector<std::uint32_t>>(n)};
  for (std::size_t v = 0; v < read.size(); ++v) {
    const int owner = ranks.owner(v);
    if (read[v] != 0 && owner != ranks.rank()) {
      halo.receive[static_cast<std::size_t>(owner)].push_back(static_cast<std::uint32_t>(v));
    }
  }
  std::vector<std::vector<std::uint8_t>> asks(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(halo.receive[k].data());
    asks[k].assign(p, p + halo.receive[k].size() * sizeof(std::uint32_t));
  }
  const std::vector<std::vector<std::uint8_t>> asked = ranks.exchange->all_to_all(std::move(asks));
  for (std::size_t k = 0; k < n; ++k) {
    if (k == static_cast<std::size_t>(ranks.rank())) continue;
    if (asked[k].size() % sizeof(std::uint32_t) != 0) {
      throw std::runtime_error("bounce solver: a rank's rows of another size");
    }
    halo.send[k].resize(asked[k].size() / sizeof(std::uint32_t));
    std::memcpy(halo.send[k].data(), asked[k].data(), asked[k].size());
    for (const std::uint32_t v : halo.send[k]) {
      if (v >= read.size() || ranks.owner(v) != ranks.rank()) {
        throw std::runtime_error("bounce solver: a rank asked for rows it does not own");
      }
    }
  }
  return halo;
}

// Collective: each rank's reflected light of the rows others read, sent to them.
void exchange_halo(const RankShares& ranks, const BounceHalo& halo, RowMatrix& reflected) {
  const auto columns = static_cast<std::size_t>(reflected.cols());
  const std::size_t row_bytes = columns * sizeof(float);
  std::vector<std::vector<std::uint8_t>> out(halo.send.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].resize(halo.send[k].size() * row_bytes);
    for (std::size_t i = 0; i < halo.send[k].size(); ++i) {
      std::memcpy(out[k].data() + i * row_bytes, reflected.row(halo.send[k][i]).data(), row_bytes);
    }
  }
  const std::vector<std::vector<std::uint8_t>> in = ranks.exchange->all_to_all(std::move(out));
  for (std::size_t k = 0; k < in.size(); ++k) {
    if (k == static_cast<std::size_t>(ranks.rank())) continue;
    if (in[k].size() != halo.receive[k].size() * row_bytes) {
      throw std::runtime_error("bounce solver: a rank's rows of another size");
    }
    for (std::size_t i = 0; i < halo.receive[k].size(); ++i) {
      std::memcpy(reflected.row(halo.receive[k][i]).data(), in[k].data() + i * row_bytes,
                  row_bytes);
    }
  }
}

// reflected = diag(ρ) · (E_d + gathered) on this rank's vertex rows (its local rows of
// `direct` and `gathered`).
void reflect_mine(const RankShares& ranks, const Eigen::VectorXf& albedo, const RowMatrix& direct,
                  const RowMatrix& gathered, RowMatrix& reflected) {
  const auto mine = static_cast<std::size_t>(direct.rows());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine, kRowGrain), [&](const auto& range) {
    for (std::size_t l = range.begin(); l != range.end(); ++l) {
      const auto row = static_cast<Eigen::Index>(ranks.receiver_of_local_row(l));
      const auto local = static_cast<Eigen::Index>(l);
      reflected.row(row) = albedo[row] * (direct.row(local) + gathered.row(local));
    }
  });
}

ChannelSolution solve_channel(const Gather& g, const Eigen::VectorXf& albedo,
                              const RowMatrix& direct, const BounceSettings& settings,
                              Progress& bar, const RankShares* ranks, const BounceHalo* halo) {
  const Eigen::Index receivers = g.rows(), columns = direct.cols();
  ChannelSolution solution;
  if (settings.max_bounces <= 0 || columns == 0 || albedo.isZero(0)) {
    solution.indirect = Eigen::MatrixXf::Zero(
        halo != nullptr ? static_cast<Eigen::Index>(ranks->my_receivers()) : receivers, columns);
    bar.advance(std::max(settings.max_bounces, 1));
    return solution;
  }
  // Several ranks: this rank's rows (engine/ranks.h), `direct` its vertex rows.
  const Eigen::Index rows =
      halo != nullptr ? static_cast<Eigen::Index>(ranks->my_receivers()) : receivers;
  RowMatrix gathered = RowMatrix::Zero(rows, columns);
  RowMatrix reflected;
  // Several ranks: each gathers its blocks of rows (engine/ranks.h) and reflects its vertex
  // rows, then sends the rows other ranks read (BounceHalo).
  const auto share_reflected = [&] {
    reflect_mine(*ranks, albedo, direct, gathered, reflected);
    exchange_halo(*ranks, *halo, reflected);
  };
  if (halo != nullptr) {
    reflected = RowMatrix::Zero(g.cols(), columns);
    share_reflected();
  } else {
    reflected = albedo.asDiagonal() * direct;
  }
  while (solution.bounces < settings.max_bounces) {
    ColumnChange change =
        gather_bounce(g, reflected, direct, gathered, halo != nullptr ? ranks : nullptr);
    if (halo != nullptr) sum_change(*ranks, change);
    ++solution.bounces;
    bar.advance();
    if (max_relative_change(change) < settings.tolerance) break;
    if (solution.bounces < settings.max_bounces) {
      if (halo != nullptr) {
        share_reflected();
      } else {
        reflect(albedo, direct, gathered, reflected);
      }
    }
  }
  bar.advance(settings.max_bounces - solution.bounces);
  solution.indirect = to_column_major(gathered);
  return solution;
}

void check_sizes(const GatherOperator& gather, const Receivers& receivers,
                 const Eigen::MatrixXf& direct, const RankShares* ranks) {
  const auto receiver_count = static_cast<Eigen::Index>(receivers.size());
  if (gather.matrix.rows() != receiver_count ||
      gather.matrix.cols() != static_cast<Eigen::Index>(receivers.vertex_count) ||
      receivers.albedo.size() != receivers.size()) {
    throw std::invalid_argument("bounce solver: gather operator and receivers disagree");
  }
  if (!gather.matrix.isCompressed()) {
    throw std::invalid_argument("bounce solver: the gather operator is not compressed");
  }
  const auto rows =
      ranks != nullptr ? static_cast<Eigen::Index>(ranks->my_receivers()) : receiver_count;
  if (direct.rows() != rows) {
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

int solve_bounces_rgb(const GatherOperator& gather, const Receivers& receivers,
                      std::span<const float> direct, std::span<float> indirect, bool warm,
                      const BounceSettings& settings) {
  const Gather& g = gather.matrix;
  const std::size_t n = receivers.size(), vertices = receivers.vertex_count;
  if (g.rows() != static_cast<Eigen::Index>(n) || g.cols() != static_cast<Eigen::Index>(vertices) ||
      receivers.albedo.size() != n) {
    throw std::invalid_argument("bounce solver: gather operator, receivers and light disagree");
  }
  std::vector<float> albedo(3 * vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    const Rgb& a = receivers.albedo[v];
    albedo[3 * v] = static_cast<float>(a.r);
    albedo[3 * v + 1] = static_cast<float>(a.g);
    albedo[3 * v + 2] = static_cast<float>(a.b);
  }
  return solve_bounces_rgb(stored_rgb_gather(gather, albedo), direct, indirect, warm, settings);
}

RgbGather stored_rgb_gather(const GatherOperator& gather, std::span<const float> albedo) {
  const Gather& g = gather.matrix;
  return {static_cast<std::size_t>(g.cols()), static_cast<std::size_t>(g.rows()), albedo,
          [&g](std::size_t r, std::span<const float> reflected, float(&sum)[3]) {
            gather_rgb_row(g, static_cast<Eigen::Index>(r), reflected, sum);
          },
          nullptr};
}

int solve_bounces_rgb(const RgbGather& op, std::span<const float> direct, std::span<float> indirect,
                      bool warm, const BounceSettings& settings) {
  const std::size_t n = op.rows, vertices = op.reflecting;
  if (vertices > n || op.albedo.size() != 3 * vertices || direct.size() != 3 * n ||
      indirect.size() != 3 * n) {
    throw std::invalid_argument("bounce solver: operator, albedo and light disagree");
  }
  std::vector<float> reflected(3 * vertices), gathered(3 * vertices, 0.0f);
  if (warm) std::copy_n(indirect.begin(), 3 * vertices, gathered.begin());
  // reflected = diag(ρ) · (E_d + gathered) on the reflecting rows.
  const auto reflect = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, 3 * vertices, 1024), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        reflected[i] = op.albedo[i] * (direct[i] + gathered[i]);
      }
    });
  };
  const double tolerance =
      warm ? std::max(settings.tolerance, kWarmBounceTolerance) : settings.tolerance;
  int bounces = 0;
  if (settings.max_bounces > 0) {
    reflect();
    while (bounces < settings.max_bounces) {
      if (op.prepare) op.prepare(reflected, false);
      // Per channel: Σ (E(n+1) − E(n))² and Σ E(n+1)²; the slowest channel decides.
      using Change = std::array<double, 6>;
      const Change change = tbb::parallel_deterministic_reduce(
          tbb::blocked_range<std::size_t>(0, vertices, kRowGrain), Change{},
          [&](const tbb::blocked_range<std::size_t>& range, Change c) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
              float sum[3];
              op.gather_row(i, reflected, sum);
              for (std::size_t k = 0; k < 3; ++k) {
                const std::size_t at = 3 * i + k;
                const double d = double{sum[k]} - gathered[at], e = double{direct[at]} + sum[k];
                c[k] += d * d;
                c[3 + k] += e * e;
                gathered[at] = sum[k];
              }
            }
            return c;
          },
          [](Change a, const Change& b) {
            for (std::size_t k = 0; k < a.size(); ++k) a[k] += b[k];
            return a;
          });
      double worst = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        if (change[3 + k] > 0) worst = std::max(worst, std::sqrt(change[k] / change[3 + k]));
      }
      ++bounces;
      reflect();
      if (worst < tolerance) break;
    }
  }
  // The reflecting rows' interreflected light, and the rest gathered once from the last light.
  std::copy(gathered.begin(), gathered.end(), indirect.begin());
  if (op.prepare && bounces > 0 && n > vertices) op.prepare(reflected, true);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(vertices, n, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      float sum[3] = {0, 0, 0};
      if (bounces > 0) op.gather_row(r, reflected, sum);
      std::copy_n(sum, 3, indirect.begin() + 3 * r);
    }
  });
  return bounces;
}

BounceResult solve_bounces(const GatherOperator& gather, const Receivers& receivers,
                           const Eigen::MatrixXf& direct, const BounceSettings& settings,
                           bool progress, const RankShares* ranks) {
  const auto start = std::chrono::steady_clock::now();
  // Several ranks: the rows they exchange, the same for every channel; `direct` holds this
  // rank's rows.
  const std::optional<RankShares> blocks =
      ranks != nullptr && !ranks->alone()
          ? std::optional(dealt_blocks(*ranks->exchange, receivers.size(),
                                       static_cast<std::size_t>(kRowGrain)))
          : std::nullopt;
  check_sizes(gather, receivers, direct, blocks ? &*blocks : nullptr);
  const std::optional<BounceHalo> halo =
      blocks ? std::optional(bounce_halo(gather.matrix, *blocks,
                                         static_cast<Eigen::Index>(receivers.vertex_count)))
             : std::nullopt;
  const RowMatrix direct_vertices = direct.topRows(static_cast<Eigen::Index>(
      blocks ? blocks->my_receivers_below(receivers.vertex_count) : receivers.vertex_count));

  BounceResult result;
  result.ranks = ranks;
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
        solve_channel(gather.matrix, albedo[c], direct_vertices, settings, bar,
                      blocks ? &*blocks : nullptr, halo ? &*halo : nullptr);
    result.indirect[c] = std::move(solution.indirect);
    result.bounces = std::max(result.bounces, solution.bounces);
  }
  bar.finish();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relight
