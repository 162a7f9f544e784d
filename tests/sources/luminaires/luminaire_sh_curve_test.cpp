// Interactive curve editing (sources/luminaires/luminaire_sh_curve.h, Dobashi et al. 1995 Eq. 21):
// the incrementally updated SH weights equal a full Eq. 19 recomputation after every move, and
// agree with the support-piece projection of luminaire_world_sh.
#include "sources/luminaires/luminaire_sh_curve.h"

#include <gtest/gtest.h>

#include "support/sh_compare.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "math/sampling.h"
#include "math/sh.h"

namespace relight {
namespace {

using testing::max_abs;
using testing::max_abs_diff;

CurveModel curve_deg(const std::vector<double>& gamma_deg, const std::vector<double>& candela) {
  CurveModel m;
  for (const double g : gamma_deg) m.gamma_rad.push_back(radians(g));
  m.candela = candela;
  return m;
}

void random_moves(CurveProjector& p, Vec3 aim, Pcg32& rng, int moves) {
  double worst = 0.0;
  for (int i = 0; i < moves; ++i) {
    const CurveModel m = curve_model(p);
    const int n = static_cast<int>(m.gamma_rad.size());
    const int k = static_cast<int>(rng.next_u32() % static_cast<std::uint32_t>(n));
    const double value = 2000.0 * rng.next_double();
    if (k == 0 || rng.next_u32() % 3 == 0) {
      move_curve_point(p, k, value);
    } else {
      const double lo = m.gamma_rad[k - 1];
      const double hi = k + 1 < n ? m.gamma_rad[k + 1] : std::min(kPi, m.gamma_rad[k] + 0.3);
      move_curve_point(p, k, lo + (hi - lo) * (0.05 + 0.9 * rng.next_double()), value);
    }
    const auto incremental = curve_world_sh(p, aim);
    const auto full = recomputed_curve_world_sh(p, aim);
    const double rel = max_abs_diff(incremental, full) / max_abs(full);
    worst = std::max(worst, rel);
    ASSERT_LT(rel, 1e-10) << "move " << i;
  }
  // A projector built afresh from the edited control points gives the same weights.
  const CurveProjector fresh = make_curve_projector(curve_model(p), p.settings);
  const auto from_scratch = curve_world_sh(fresh, aim);
  EXPECT_LT(max_abs_diff(curve_world_sh(p, aim), from_scratch) / max_abs(from_scratch), 1e-10);
  std::cout << moves << " moves: worst |incremental − full| / max = " << worst << "\n";
}

TEST(LuminaireShCurve, IncrementalUpdateEqualsFullRecomputation) {
  // Ends at π: the paper's setting.
  CurveProjector p = make_curve_projector(
      curve_deg({0, 15, 30, 45, 60, 90, 120, 180}, {1000, 950, 800, 500, 200, 50, 10, 0}),
      {.order = 8});
  Pcg32 rng(42, 3);
  random_moves(p, normalize(Vec3{0.2, -1, 0.1}), rng, 100);
}

TEST(LuminaireShCurve, IncrementalUpdateEqualsFullRecomputationBeforePi) {
  // Ends at 70° with a step to zero: the last point drags the internal ramp point along.
  CurveProjector p = make_curve_projector(curve_deg({0, 20, 40, 70}, {800, 700, 300, 100}),
                                          {.order = 16, .window = ShWindow::kHanning});
  Pcg32 rng(8, 8);
  random_moves(p, Vec3{0, 0, 1}, rng, 100);
}

TEST(LuminaireShCurve, AgreesWithTheSupportPieceProjection) {
  const Vec3 aim = normalize(Vec3{1, -3, 0.5});
  // A curve ending in zero: only the kinks differ between the uniform grid and the pieces.
  const CurveModel smooth_end = curve_deg({0, 10, 25, 40, 60}, {1200, 1100, 600, 150, 0});
  const auto uniform = curve_world_sh(make_curve_projector(smooth_end), aim);
  const auto pieces = luminaire_world_sh(Distribution{smooth_end}, aim, {1, 0, 0});
  const double rel = max_abs_diff(uniform, pieces) / max_abs(pieces);
  EXPECT_LT(rel, 1e-5);
  // Flat cones: the step at the cut-off would be an O(Δγ) error on the uniform grid (up to
  // 0.5 % of the flux at 20°); the jump correction removes it.
  double worst_cone = 0.0;
  for (const double cut : {5.0, 20.0, 30.0, 47.3, 90.0, 150.0}) {
    const CurveModel cone = curve_deg({0, cut}, {1000, 1000});
    const Distribution cone_d{cone};
    const auto projector = curve_world_sh(make_curve_projector(cone), aim);
    const auto pieces = luminaire_world_sh(cone_d, aim, {1, 0, 0});
    EXPECT_LT(std::abs(sh_flux_lm(pieces) / cone_d.flux_lm() - 1.0), 1e-9) << cut;
    const double flux_err = std::abs(sh_flux_lm(projector) / cone_d.flux_lm() - 1.0);
    EXPECT_LT(flux_err, 1e-5) << cut;
    const double cone_rel = max_abs_diff(projector, pieces) / max_abs(pieces);
    EXPECT_LT(cone_rel, 1e-5) << cut;
    worst_cone = std::max({worst_cone, flux_err, cone_rel});
  }
  RecordProperty("smooth_end_relative_difference", std::to_string(rel));
  RecordProperty("cone_worst_relative_difference", std::to_string(worst_cone));
  std::cout << "uniform grid vs pieces: " << rel << " (curve ending in 0); flat cones "
            << worst_cone << "\n";
}

TEST(LuminaireShCurve, BadMovesLeaveTheProjectorUnchanged) {
  CurveProjector p = make_curve_projector(curve_deg({0, 30, 60}, {100, 80, 20}));
  const auto before = curve_world_sh(p, {0, 0, 1});
  EXPECT_THROW(move_curve_point(p, 3, 1.0), std::out_of_range);
  EXPECT_THROW(move_curve_point(p, 1, radians(70), 1.0), std::invalid_argument);
  EXPECT_THROW(move_curve_point(p, 2, radians(20), 1.0), std::invalid_argument);
  EXPECT_THROW(move_curve_point(p, 2, kPi, 1.0), std::invalid_argument);
  EXPECT_EQ(curve_world_sh(p, {0, 0, 1}), before);
  EXPECT_THROW(make_curve_projector(curve_deg({5, 30}, {1, 1})), std::invalid_argument);
}

}  // namespace
}  // namespace relight
