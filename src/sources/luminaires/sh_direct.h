// Direct irradiance of each SH basis intensity distribution (Dobashi et al.
// 1995's basis luminances before interreflection, Eq. 14–16): a luminaire emitting
// I(ω) = Y_k(ω) (world frame, ω from the luminaire) gives receiver r the irradiance
// Y_k(ω_r) · g_r, g_r the direct geometry factor. These columns seed the bounce solver
// and, in "direct": "sh" mode, are the direct light itself.
#pragma once

#include <Eigen/Dense>

#include "sources/luminaires/luminaire_direct.h"

namespace relight {

Eigen::MatrixXf sh_basis_direct(const DirectGeometry& geometry, int sh_order);

}  // namespace relight
