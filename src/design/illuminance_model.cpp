#include "design/illuminance_model.h"

#include <stdexcept>

namespace relight {

namespace {

// Lux (Y) of every model row as `relit` is lit now.
std::vector<double> model_lux(const RelitScene& relit, std::span<const ModelSet> sets) {
  const std::vector<std::vector<double>> lux = sensor_set_lux(relit);
  std::vector<double> out;
  for (const ModelSet& s : sets) out.insert(out.end(), lux[s.set].begin(), lux[s.set].end());
  return out;
}

LightingState with_free_off(LightingState state, std::span<const std::size_t> free) {
  for (const std::size_t j : free) state.luminaires[j].on = false;
  return state;
}

void set_column(IlluminanceModel& model, std::size_t j, std::span<const double> lit) {
  const std::size_t m = model.free.size();
  for (std::size_t r = 0; r < model.rows(); ++r) model.columns[r * m + j] = lit[r] - model.base[r];
}

}  // namespace

std::vector<std::vector<double>> sensor_set_lux(const RelitScene& relit) {
  const Scene& scene = relit.scene();
  const std::vector<Rgb> e = relit.sensor_irradiance();
  std::vector<std::vector<double>> out(scene.sensors.size());
  std::size_t point = 0;
  for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
    for (std::size_t i = 0; i < scene.sensors[s].points.size(); ++i) {
      out[s].push_back(luminance(e[point++]));
    }
  }
  return out;
}

double IlluminanceModel::lux(std::size_t row, std::span<const double> d) const {
  double e = base[row];
  const double* a = &columns[row * free.size()];
  for (std::size_t j = 0; j < free.size(); ++j) e += a[j] * d[j];
  return e;
}

const ModelSet& IlluminanceModel::rows_of(std::size_t set) const {
  for (const ModelSet& s : sets) {
    if (s.set == set) return s;
  }
  throw std::logic_error("IlluminanceModel::rows_of: the model does not read this set");
}

IlluminanceModel illuminance_model(RelitScene& relit, const LightingState& base,
                                   std::span<const std::size_t> free,
                                   std::span<const std::size_t> sets) {
  const Scene& scene = relit.scene();
  IlluminanceModel model;
  model.free.assign(free.begin(), free.end());
  std::size_t rows = 0;
  for (const std::size_t s : sets) {
    model.sets.push_back({s, rows, scene.sensors.at(s).points.size()});
    rows += scene.sensors[s].points.size();
  }
  LightingState state = with_free_off(base, free);
  relit.apply(state);
  model.base = model_lux(relit, model.sets);
  model.columns.assign(rows * free.size(), 0.0);
  for (std::size_t j = 0; j < free.size(); ++j) {
    LuminaireState& l = state.luminaires[free[j]];
    l.on = true;
    l.dimmer = 1;
    relit.apply(state);
    set_column(model, j, model_lux(relit, model.sets));
    l.on = false;
  }
  relit.apply(state);
  return model;
}

void update_model_column(IlluminanceModel& model, RelitScene& relit, const LightingState& base,
                         std::size_t j, const LuminaireState& luminaire) {
  LightingState state = with_free_off(base, model.free);
  LuminaireState& l = state.luminaires[model.free.at(j)];
  l = luminaire;
  l.on = true;
  l.dimmer = 1;
  relit.apply(state);
  set_column(model, j, model_lux(relit, model.sets));
}

}  // namespace relight
