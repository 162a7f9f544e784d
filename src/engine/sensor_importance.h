// The sensors' rows of the bounce, solved once, so that a year of daylight takes seconds. The run
// time bounces light it computes itself — the exact sun, near-field emitters — through the stored
// gather operator (bounce_solver.h solve_bounces_rgb): per channel c,
//
//   E = E_d + G_vv · diag(ρ_c) · E,    I_s = g_s · diag(ρ_c) · E   at sensor s,
//
// g_s the sensor's row of G. A caller that reads only the sensors (`relight annual`: 414
// sensors, four thousand suns) need not solve the room for every light: I_s is linear in E_d,
//
//   I_s = w_s,c · E_d,    w_s,c = diag(ρ_c) · (I − G_vvᵀ · diag(ρ_c))⁻¹ · g_sᵀ,
//
// the sensor's importance (the adjoint of the bounce; Christensen et al. 1993, "Importance-
// driven wavelet radiance", transport the sensors' importance the way light is transported).
// All sensors' importance is the same Jacobi iteration as the precompute's, with Gᵀ for G and
// the sensors' rows as its K columns: u = g_sᵀ + G_vvᵀ · diag(ρ_c) · u, one solve_bounces call
// (the same tolerance, so both sides of the adjoint stop equally close to the series' sum), then
// w = diag(ρ_c) · u. After that a light's bounce at every sensor is a dot product over the
// vertices it lights. Pinned against solve_bounces_rgb by tests/engine/sensor_importance_test.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "engine/bounce_solver.h"
#include "engine/gather_operator.h"
#include "engine/receivers.h"

namespace relight {

struct SensorImportance {
  std::size_t vertices = 0, sensors = 0;
  // Per channel (r, g, b), vertex-major: weights[c][v · sensors + s] = w_s,c[v].
  std::array<std::vector<float>, 3> weights;
  int bounces = 0;  // of the adjoint solve (the most over channels)
  double seconds = 0;
};

// The importance of every sensor row of `gather` (receivers: vertices, then sensors; the
// vertices' albedo from `receivers`). Throws std::invalid_argument when sizes disagree.
SensorImportance sensor_importance(const GatherOperator& gather, const Receivers& receivers,
                                   const BounceSettings& settings);

// What solve_bounces_rgb would give at the sensor rows for the light `direct` (3 per
// receiver; its vertex rows are what the surfaces reflect): out[3s + c] = w_s,c · E_d,c.
// Allocates only the list of lit vertices. Throws std::invalid_argument when sizes disagree.
void sensor_indirect(const SensorImportance& importance, std::span<const float> direct,
                     std::span<float> out);

}  // namespace relight
