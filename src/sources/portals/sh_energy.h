// How much each SH order of a portal's stored indirect transfer can carry: the order
// analysis of Yue et al. 2009 (§4.2 "Evaluation on Using
// Low-order SH", Eq. 4–5, Figure 8). For a shell radiance whose order-l coefficients are
// c_l, the mean square over the N_v vertices of the light they bring is (Eq. 4)
//   \bar L_l² = (1/N_v) Σ_v (Σ_m c_lm t_lm^{p,v})²,
// and its maximum over unit c_l (Σ_m c_lm² = 1, Eq. 5) is the largest eigenvalue of
// (1/N_v) T_lᵀ T_l, T_l the N_v × (2l+1) matrix of the transfer coefficients of order l
// (Rayleigh quotient). Per order and colour channel, with each order's share of the sum
// over the stored orders (Figure 8 (a)) and the cumulative share (Figure 8 (b)): with the
// shell's energy spread evenly over the orders, the part of it that truncating after
// order l keeps.
//
// t is the portal's stored *indirect* transfer ("PI" sections: interreflected irradiance,
// light reflected at least once, per unit basis radiance of the shell; the albedo of the
// reflecting surfaces is in it); the direct part is stored as per-receiver cubemaps and is
// not analysed here. Only the vertices count, not the sensors stored after them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "math/rgb.h"
#include "sources/portals/portal_transfer_view.h"

namespace relight {

struct ShOrderEnergy {
  int l = 0;
  std::array<double, 3> energy{};      // max over unit c_l of \bar L_l², per channel r, g, b
  std::array<double, 3> share{};       // energy / Σ over orders (0 when that sum is 0)
  std::array<double, 3> cumulative{};  // Σ of shares of orders 0..l (1 at the last order)
};

// One entry per order l < sh_order. `receivers` is the stored receiver count (vertices
// first, then sensors), `vertex_count` ≤ receivers the vertices analysed; portal.indirect
// must hold blocked_floats(receivers, sh_order², 3) floats (engine/transfer_blocks.h).
// Throws std::invalid_argument otherwise. With no vertices every energy is 0.
std::vector<ShOrderEnergy> portal_sh_energy(const PortalTransferView& portal,
                                            std::size_t vertex_count, std::size_t receivers,
                                            int sh_order);

// The other factor of the light each order brings: the shell's own energy per order,
// Σ_m c_lm² per channel (cd²/m⁴), from its coefficients `sh` (sh_order² of them, math/sh.h
// order). The relighter's shell holds the sky and the ground but not a sun it traces exactly
// (sources/portals/portal_sun.h), so this is the energy the SH path actually carries.
std::vector<std::array<double, 3>> shell_order_energy(const std::vector<Rgb>& sh, int sh_order);

}  // namespace relight
