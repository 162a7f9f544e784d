// The bounce solver of the interreflection engine: every basis column of direct irradiance (one per
// SH basis function of a luminaire, per portal basis, …; geometry-only, scalar) bounces through the
// same gather operator G, all columns at once, one colour channel at a time (albedo colours the
// light):
//
//   E_c(0) = E_d,   E_c(n+1) = E_d + G_vv · diag(ρ_c) · E_c(n)   (vertex rows)
//
// until max over columns of ‖E(n+1) − E(n)‖ / ‖E(n+1)‖ < tolerance. The result is the
// interreflected part only, I_c = G · diag(ρ_c) · E_c, for every receiver (vertex and
// sensor rows): the total irradiance is E_d + I_c.
//
// Dobashi et al. 1995 (Eq. 16–17) solves one radiosity system
// per basis luminance, sharing only the form factors; Yue et al. 2009 (Yue et al. 2009,
// §4.1.1) traces a photon map per SH basis. Here one sparse × dense product per bounce
// advances all K basis columns together, and no ray is traced after G is built.
#pragma once

#include <array>
#include <functional>
#include <span>

#include <Eigen/Core>

#include "engine/gather_operator.h"
#include "engine/ranks.h"
#include "engine/receivers.h"

namespace relight {

struct BounceSettings {
  double tolerance = 1e-4;  // relative change per bounce that ends the iteration
  int max_bounces = 100;    // 0: no interreflection at all
};

struct BounceResult {
  // receivers × K per channel (r, g, b), lux; on one of several ranks, its rows only (ranks).
  std::array<Eigen::MatrixXf, 3> indirect;
  const RankShares* ranks = nullptr;  // the ranks solve_bounces was given
  int bounces = 0;  // products G · diag(ρ) · E computed, the most over channels
  double seconds = 0;
};

// `direct` is receivers × K (sensor rows are accepted and not used: sensors do not
// reflect). The albedo is receivers.albedo of the vertex rows. Channels whose albedo
// equals an earlier channel's are copied, not solved again. Throws std::invalid_argument
// when the sizes of gather, receivers and direct disagree. With several `ranks` (engine/ranks.h;
// collective), `direct` and the result hold this rank's rows only (RankShares::local_row), `gather`
// needs only its rows, and each bounce the ranks exchange the reflected light of the vertex rows
// other ranks' rows read (only those); the bounces' values are those of one process, and the
// convergence norms are summed over ranks in rank order.
BounceResult solve_bounces(const GatherOperator& gather, const Receivers& receivers,
                           const Eigen::MatrixXf& direct, const BounceSettings& settings,
                           bool progress, const RankShares* ranks = nullptr);

// A warm start stops once a bounce changes the light by less than this (or the settings'
// tolerance, if larger): the error left is then below kWarmBounceTolerance / (1 − ρ) of the
// light — a few tenths of a percent — and does not accumulate over frames, since every solve
// contracts what it starts from. A sun moved a minute then takes a bounce or two instead of four
// (each a pass over G, bound by random reads; measured: docs/decisions.md).
inline constexpr double kWarmBounceTolerance = 1e-3;

// One coloured source's light, bounced at run time (light the run time computes exactly, the sun
// behind clear glass and near-field emitters): `direct` and `indirect` hold 3 floats per receiver
// (r, g, b), channel c bouncing with the albedo's channel c. The same iteration as above, on the
// vertex rows only and all three channels in one pass over G per bounce; the sensor rows are
// gathered once from the converged light. With `warm`, `indirect` holds a previous solution (of a
// slightly different direct light: the sun a minute on, an emitter a centimetre away) and the
// iteration starts from it, which takes a few bounces instead of the ~log(tolerance)/log(ρ) from
// the direct light alone. Returns the bounces computed. Throws std::invalid_argument when sizes
// disagree.
int solve_bounces_rgb(const GatherOperator& gather, const Receivers& receivers,
                      std::span<const float> direct, std::span<float> indirect, bool warm,
                      const BounceSettings& settings);

// A gather operator given row by row, for light the run time bounces through more than the
// stored G (the room's rows extended by movable objects', sources/objects/object_transfer.h):
// rows [0, reflecting) reflect with `albedo` (3 per row) and are solved for; rows
// [reflecting, rows) (sensors) are gathered once from the converged light. gather_row(i,
// reflected, sum) sets sum to Σ_j A_ij · reflected[3j … 3j+2] (RGB), j < reflecting; it is
// called from many threads at once. `prepare(reflected, last)`, when set, is called once before
// each sweep of gather_row over a new reflected light (what rows share: values at proxies);
// with `last`, before the one pass over rows [reflecting, rows) alone.
struct RgbGather {
  std::size_t reflecting = 0, rows = 0;
  std::span<const float> albedo;
  std::function<void(std::size_t row, std::span<const float> reflected, float (&sum)[3])>
      gather_row;
  std::function<void(std::span<const float> reflected, bool last)> prepare;
};

// The iteration of the solve_bounces_rgb above over such an operator: `direct` and
// `indirect` hold 3 floats per row. Throws std::invalid_argument when sizes disagree.
int solve_bounces_rgb(const RgbGather& op, std::span<const float> direct, std::span<float> indirect,
                      bool warm, const BounceSettings& settings);

// The stored operator as an RgbGather whose vertices reflect `albedo` (3 per vertex); both must
// outlive it.
RgbGather stored_rgb_gather(const GatherOperator& gather, std::span<const float> albedo);

// Σ_j G_rj · reflected[3j … 3j+2] of one row of a stored gather operator.
void gather_rgb_row(const Eigen::SparseMatrix<float, Eigen::RowMajor>& gather, Eigen::Index row,
                    std::span<const float> reflected, float (&sum)[3]);

}  // namespace relight
