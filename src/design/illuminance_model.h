// The sensors' illuminance as a linear function of the luminaires' dimmers: at every sensor point i
// the relit scene gives
//   E_i(d) = b_i + Σ_j A_ij d_j
// exactly, because everything the Relighter sums is linear in each luminaire's output (its
// direct light, its SH-projected interreflection, Dobashi et al. 1995 Eq. 18, and the material,
// glossy and movable-object terms bounced from it). b is the light with the free luminaires
// off (daylight, fixed luminaires, emitters as the state has them); column j the light of
// luminaire j alone at dimmer 1, read as the difference of two relights. Lux is the Y of the
// RGB reading, as `relight probe` prints it. Tests: tests/design/illuminance_model_test.cpp
// (the model against the relit scene at random dimmers, within 1e-5).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "runtime/lighting_state.h"
#include "runtime/relit_scene.h"

namespace relight {

// A sensor set's rows in the model.
struct ModelSet {
  std::size_t set = 0;               // index into scene.sensors
  std::size_t first = 0, count = 0;  // rows [first, first + count)
};

struct IlluminanceModel {
  std::vector<std::size_t> free;  // the luminaires (scene order) whose dimmers are the unknowns
  std::vector<ModelSet> sets;     // the sets the model reads, scene order
  std::vector<double> base;       // lx per row with every free luminaire off
  std::vector<double> columns;    // rows × free.size(), row-major: lx per unit of dimmer

  std::size_t rows() const { return base.size(); }
  double column(std::size_t row, std::size_t j) const { return columns[row * free.size() + j]; }
  // E_i at dimmers d (free.size()).
  double lux(std::size_t row, std::span<const double> d) const;
  // The rows of scene sensor set `set` (it must be one the model reads).
  const ModelSet& rows_of(std::size_t set) const;
};

// Each sensor set's readings (lx, the Y of RGB as `relight probe` prints them) as `relit` is
// lit now, by scene set index.
std::vector<std::vector<double>> sensor_set_lux(const RelitScene& relit);

// The model of `sets` (scene indices, ascending) with `free` varied in `base` (their `on` and
// dimmer in `base` are ignored; everything else — aim, colour, distribution — is as `base` sets
// it). Relights `relit` free.size() + 1 times; leaves it lit by `base` with the free ones off.
IlluminanceModel illuminance_model(RelitScene& relit, const LightingState& base,
                                   std::span<const std::size_t> free,
                                   std::span<const std::size_t> sets);

// Column j of `model` again with free luminaire j set as `luminaire` (at dimmer 1): after an
// aim changed. One relight.
void update_model_column(IlluminanceModel& model, RelitScene& relit, const LightingState& base,
                         std::size_t j, const LuminaireState& luminaire);

}  // namespace relight
