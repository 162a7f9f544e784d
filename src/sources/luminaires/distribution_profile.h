// The distribution editor's view of a luminaire (Dobashi et al. 1995 §4.1
// and Fig. 4): its intensity I(γ) in the C0, C90, C180 and C270 half-planes, exact and as the
// relighter approximates it for the interreflected light: SH bands l < order, without and
// with the window (Eq. 12-13). The approximations are the projection of
// sources/luminaires/luminaire_sh.h (project_luminaire_local) evaluated in the luminaire's own
// frame, so they show exactly what the band limit and the window do to the curve.
#pragma once

#include <array>
#include <vector>

#include "light/distribution.h"
#include "math/sh_window.h"

namespace relight {

struct DistributionProfile {
  std::vector<double> gamma_deg;  // 0 .. 180, `samples` values
  // [half-plane] C0, C90, C180, C270; candela at each γ.
  std::array<std::vector<double>, 4> exact, sh, sh_windowed;
  double flux_lm = 0;  // of the distribution itself
};

inline constexpr std::array<double, 4> kProfilePlanesDeg = {0, 90, 180, 270};

// samples ≥ 2; order ≥ 1. std::invalid_argument otherwise.
DistributionProfile distribution_profile(const Distribution& distribution, int order,
                                         ShWindow window, int samples);

}  // namespace relight
