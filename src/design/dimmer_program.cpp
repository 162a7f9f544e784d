#include "design/dimmer_program.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "design/linear_program.h"

namespace relight {

namespace {

constexpr double kMargin = 1e-6;          // relative: lower bounds asked above, upper below
constexpr double kUniformityStep = 1e-5;  // U0 differences below this are ties
constexpr int kMaxDinkelbachSteps = 50;

// Mean of the set's rows: the Em row (coefficients per free luminaire, and its constant).
struct MeanRow {
  std::vector<double> a;
  double b = 0;
};

MeanRow mean_row(const IlluminanceModel& model, const ModelSet& set) {
  MeanRow m;
  m.a.assign(model.free.size(), 0.0);
  for (std::size_t r = set.first; r < set.first + set.count; ++r) {
    m.b += model.base[r];
    for (std::size_t j = 0; j < model.free.size(); ++j) m.a[j] += model.column(r, j);
  }
  const double n = static_cast<double>(set.count);
  m.b /= n;
  for (double& v : m.a) v /= n;
  return m;
}

// Builds the programs: columns d_0..d_{m-1}, then (with slacks) one slack per target.
class ProgramBuilder {
 public:
  // Columns: the dimmers, one slack per target (with `slacks`), then `extra` more (bounds
  // [0, ∞) until the caller sets them).
  ProgramBuilder(const DimmerProblem& p, bool slacks, std::size_t extra = 0)
      : p_(p), m_(p.model->free.size()) {
    const std::size_t cols = m_ + (slacks ? p.targets.size() : 0) + extra;
    lp_.cols = cols;
    lp_.c.assign(cols, 0.0);
    lp_.col_lo.assign(cols, 0.0);
    lp_.col_hi.assign(cols, kLpInfinity);
    for (std::size_t j = 0; j < m_; ++j) {
      lp_.col_lo[j] = p.lo[j];
      lp_.col_hi[j] = p.hi[j];
    }
    for (std::size_t k = 0; k < p.targets.size(); ++k) {
      add_target(k, slacks ? std::optional<std::size_t>(m_ + k) : std::nullopt);
    }
  }

  LinearProgram& program() { return lp_; }

  // Σ w d as the objective.
  void minimise_power() {
    for (std::size_t j = 0; j < m_; ++j) lp_.c[j] = p_.watts[j];
  }

  // E_i − t · Em ≥ z at every point of `set`, z the column `z` (or 0 without one).
  void add_uniformity(const ModelSet& set, double t, std::optional<std::size_t> z) {
    const MeanRow mean = mean_row(*p_.model, set);
    std::vector<double> row(lp_.cols, 0.0);
    if (z) row[*z] = -1;
    for (std::size_t r = set.first; r < set.first + set.count; ++r) {
      for (std::size_t j = 0; j < m_; ++j) row[j] = p_.model->column(r, j) - t * mean.a[j];
      lp_.add_row(row, t * mean.b - p_.model->base[r], kLpInfinity);
    }
  }

 private:
  // The target's rows; with a slack column, the slack (in units of `scale`) relaxes them.
  void add_target(std::size_t k, std::optional<std::size_t> slack) {
    const Target& t = p_.targets[k];
    const IlluminanceModel& model = *p_.model;
    const ModelSet& set = model.rows_of(t.set);
    const double v = t.value;
    const bool lower = is_lower_bound(t.kind);
    double scale = std::max(v, 1.0);
    const double margin = kMargin * scale;
    std::vector<double> row(lp_.cols, 0.0);
    const auto add = [&](double constant, double bound) {
      // lower: row·x + constant ≥ bound (+ slack); upper: row·x + constant ≤ bound (− slack).
      if (slack) row[*slack] = lower ? scale : -scale;
      if (lower) {
        lp_.add_row(row, bound - constant, kLpInfinity);
      } else {
        lp_.add_row(row, -kLpInfinity, bound - constant);
      }
    };
    switch (t.kind) {
      case TargetKind::kEmMin:
      case TargetKind::kEmMax: {
        const MeanRow mean = mean_row(model, set);
        std::copy(mean.a.begin(), mean.a.end(), row.begin());
        add(mean.b, lower ? v + margin : v - margin);
        break;
      }
      case TargetKind::kEMin:
      case TargetKind::kEMax:
        for (std::size_t r = set.first; r < set.first + set.count; ++r) {
          for (std::size_t j = 0; j < m_; ++j) row[j] = model.column(r, j);
          add(model.base[r], lower ? v + margin : v - margin);
        }
        break;
      case TargetKind::kU0Min: {
        const MeanRow mean = mean_row(model, set);
        const double u = v + kMargin;
        // The slack's unit: u · Em with every free dimmer at its top.
        double top = mean.b;
        for (std::size_t j = 0; j < m_; ++j) top += mean.a[j] * p_.hi[j];
        scale = std::max(u * top, 1e-9);
        for (std::size_t r = set.first; r < set.first + set.count; ++r) {
          for (std::size_t j = 0; j < m_; ++j) row[j] = model.column(r, j) - u * mean.a[j];
          add(model.base[r] - u * mean.b, 0.0);
        }
        break;
      }
    }
  }

  const DimmerProblem& p_;
  std::size_t m_;
  LinearProgram lp_;
};

LpSolution solve_counted(const LinearProgram& lp, DimmerSolution& out) {
  LpSolution s = solve_linear_program(lp);
  out.iterations += s.iterations;
  ++out.programs;
  if (s.status == LpStatus::kFailed) {
    throw std::runtime_error("the linear program solver (CLP) failed on the dimmer program");
  }
  return s;
}

// The sets whose U0 "uniformity" maximises: those with a level target above 0.
std::vector<std::size_t> level_sets(std::span<const Target> targets) {
  std::vector<std::size_t> sets;
  for (const Target& t : targets) {
    if ((t.kind == TargetKind::kEmMin || t.kind == TargetKind::kEMin) && t.value > 0 &&
        std::find(sets.begin(), sets.end(), t.set) == sets.end()) {
      sets.push_back(t.set);
    }
  }
  return sets;
}

double smallest_u0(const IlluminanceModel& model, std::span<const std::size_t> sets,
                   std::span<const double> d) {
  double u = std::numeric_limits<double>::infinity();
  for (const std::size_t s : sets)
    u = std::min(u, model_value(model, {s, TargetKind::kU0Min, 0}, d));
  return sets.empty() ? 0.0 : u;
}

void finish(const DimmerProblem& p, std::vector<double> x, DimmerSolution& out) {
  x.resize(p.model->free.size());
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = std::clamp(x[j], p.lo[j], p.hi[j]);
  out.dimmers = std::move(x);
  out.power_w = std::inner_product(out.dimmers.begin(), out.dimmers.end(), p.watts.begin(), 0.0);
  out.uniformity = smallest_u0(*p.model, level_sets(p.targets), out.dimmers);
}

// The least violation, then the least power at it.
void solve_closest(const DimmerProblem& p, DimmerSolution& out) {
  const std::size_t m = p.model->free.size();
  ProgramBuilder least(p, true);
  for (std::size_t k = 0; k < p.targets.size(); ++k) least.program().c[m + k] = 1;
  const LpSolution s = solve_counted(least.program(), out);
  if (s.status != LpStatus::kOptimal) {
    throw std::runtime_error("the dimmer program with slacks has no optimum");
  }
  out.violation = s.objective;
  ProgramBuilder cheapest(p, true);
  cheapest.minimise_power();
  std::vector<double> sum(cheapest.program().cols, 0.0);
  for (std::size_t k = 0; k < p.targets.size(); ++k) sum[m + k] = 1;
  cheapest.program().add_row(sum, -kLpInfinity, s.objective * (1 + 1e-7) + 1e-9);
  const LpSolution c = solve_counted(cheapest.program(), out);
  finish(p, c.status == LpStatus::kOptimal ? c.x : s.x, out);
}

}  // namespace

double set_value(std::span<const double> lux, TargetKind kind) {
  double sum = 0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double e : lux) {
    sum += e;
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  const double mean = sum / static_cast<double>(lux.size());
  switch (kind) {
    case TargetKind::kEmMin:
    case TargetKind::kEmMax:
      return mean;
    case TargetKind::kEMin:
      return lo;
    case TargetKind::kEMax:
      return hi;
    case TargetKind::kU0Min:
      return mean > 0 ? lo / mean : 0.0;
  }
  return 0;
}

double model_value(const IlluminanceModel& model, const Target& target, std::span<const double> d) {
  const ModelSet& set = model.rows_of(target.set);
  std::vector<double> lux(set.count);
  for (std::size_t r = 0; r < set.count; ++r) lux[r] = model.lux(set.first + r, d);
  return set_value(lux, target.kind);
}

DimmerSolution solve_dimmers(const DimmerProblem& p) {
  const std::size_t m = p.model->free.size();
  if (p.lo.size() != m || p.hi.size() != m || p.watts.size() != m) {
    throw std::logic_error(
        "solve_dimmers: bounds and watts must have one value per free luminaire");
  }
  DimmerSolution out;
  ProgramBuilder power(p, false);
  power.minimise_power();
  const LpSolution first = solve_counted(power.program(), out);
  if (first.status != LpStatus::kOptimal) {
    solve_closest(p, out);
    return out;
  }
  out.feasible = true;
  finish(p, first.x, out);
  if (p.objective != DesignObjective::kUniformity) return out;

  // The largest smallest-U0 of the level sets, a generalised fractional program
  // max_d min_s N_s(d) / D_s(d) (N the set's smallest E, D its Em; both linear or concave in d,
  // D > 0), by Dinkelbach's method in its max–min form (Crouzeix, Ferland & Schaible 1985, J.
  // Optim. Theory Appl. 47(1)): at t, the program max z subject to E_i − t · Em ≥ z over
  // every level set's points; its optimum is 0 exactly at the best t, and the U0 of its
  // solution is the next t, which rises to the best in a few programs.
  const std::vector<std::size_t> sets = level_sets(p.targets);
  double t = out.uniformity;
  std::vector<double> best = out.dimmers;
  for (int step = 0; step < kMaxDinkelbachSteps; ++step) {
    ProgramBuilder b(p, false, 1);
    LinearProgram& lp = b.program();
    lp.col_lo[m] = -kLpInfinity;
    lp.c[m] = -1;  // maximise z
    for (const std::size_t s : sets) b.add_uniformity(p.model->rows_of(s), t, m);
    const LpSolution s = solve_counted(lp, out);
    if (s.status != LpStatus::kOptimal || -s.objective <= 1e-9 * std::max(1.0, t)) break;
    std::vector<double> d(s.x.begin(), s.x.begin() + static_cast<std::ptrdiff_t>(m));
    const double next = smallest_u0(*p.model, sets, d);
    if (next <= t + 1e-12) break;
    t = next;
    best = std::move(d);
  }
  // The least power at that U0 (a hair below it, so that `best` itself is feasible).
  ProgramBuilder cheapest(p, false);
  cheapest.minimise_power();
  for (const std::size_t s : sets) {
    cheapest.add_uniformity(p.model->rows_of(s), t - 1e-9, std::nullopt);
  }
  const LpSolution c = solve_counted(cheapest.program(), out);
  finish(p, c.status == LpStatus::kOptimal ? c.x : best, out);
  return out;
}

bool better_solution(const DimmerSolution& a, const DimmerSolution& b, DesignObjective objective) {
  if (std::abs(a.violation - b.violation) > 1e-9) return a.violation < b.violation;
  if (objective == DesignObjective::kUniformity && a.feasible) {
    if (std::abs(a.uniformity - b.uniformity) > kUniformityStep) return a.uniformity > b.uniformity;
  }
  return a.power_w < b.power_w * (1 - 1e-9);
}

}  // namespace relight
