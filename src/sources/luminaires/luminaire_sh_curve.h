// Interactive editing of a curve distribution (Dobashi et al. 1995 §4.1): the
// designer drags one control point of the piecewise-linear I(γ) and the SH weights follow at
// once. The projector keeps the paper's sample table (Eq. 19-20, f_l(γ_i) with the Simpson
// weights folded in, math/zonal.h LegendreCurve) and updates the Legendre weights by the
// change at the touched samples only (Eq. 21, math/zonal.h move_control_point), then windows
// (Eq. 12-13) and aims by the addition theorem (Eq. 9-10).
//
// Grid: the paper's uniform γ_i = iπ/M on [0, π], composite Simpson, M = kCurveIntervals
// (2048, Δγ ≈ 0.09°). A curve is linear between control points, so the kinks cost O(Δγ²)
// only. A CurveModel is zero beyond its last control point; when that point has γ < π the
// projector appends two internal points, (γ_last + 1e-9, 0) and (π, 0), so LegendreCurve
// (which spans 0..π) sees the same function. A non-zero value at γ_last < π is then a jump,
// which a uniform grid integrates with an O(Δγ) error: measured up to 0.5 % of the flux for
// a flat 20° cone at M = 2048, still 0.07 % at M = 16384. So the projector adds a jump
// correction: on the one Simpson panel holding γ_last, the exact panel integral (Simpson on
// its linear pieces) minus what the panel's three uniform samples give, recomputed after
// every move (O(order) work). With it the projector agrees with the support-piece projection
// of luminaire_world_sh to ~1e-6 relative (tests/sources/luminaires/luminaire_sh_curve_test.cpp).
//
// Increments equal a full Eq. 19 summation from the current control points to rounding
// (the same test: 1e-10 relative after 100 random moves).
#pragma once

#include <span>
#include <vector>

#include "light/distribution.h"
#include "math/vec3.h"
#include "math/zonal.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {

inline constexpr int kCurveIntervals = 2048;

struct CurveProjector {
  LegendreCurve curve;           // the model's control points, then the internal ones (if any)
  int point_count = 0;           // control points of the model (indices 0 .. point_count−1)
  LuminaireShSettings settings;  // order, window (simpson_intervals and path are not used)
  std::vector<double> step_correction;  // jump correction added to curve.weights (see above)
};

// Throws std::invalid_argument for a curve that does not start at γ = 0, has fewer than two
// points, non-ascending angles, or an odd / non-positive interval count.
CurveProjector make_curve_projector(const CurveModel& curve,
                                    const LuminaireShSettings& settings = {},
                                    int intervals = kCurveIntervals);

// Moves control point k to (gamma_rad, candela) by Eq. 21. γ must stay strictly between the
// neighbours (and below π − 2e-9 for the last point of a curve ending before π); the first
// point keeps γ = 0, a last point at π keeps π. Throws std::out_of_range /
// std::invalid_argument (the projector is unchanged then).
void move_curve_point(CurveProjector& projector, int k, double gamma_rad, double candela);
void move_curve_point(CurveProjector& projector, int k, double candela);

// The model's current control points.
CurveModel curve_model(const CurveProjector& projector);

// World-frame coefficients (order² values) from the incrementally kept weights; no allocation.
void curve_world_sh(const CurveProjector& projector, Vec3 aim, std::span<double> world);
std::vector<double> curve_world_sh(const CurveProjector& projector, Vec3 aim);

// The same from a full Eq. 19 summation over the current control points (the reference the
// increments must equal).
std::vector<double> recomputed_curve_world_sh(const CurveProjector& projector, Vec3 aim);

}  // namespace relight
