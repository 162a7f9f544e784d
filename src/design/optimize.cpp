#include "design/optimize.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "design/aim_search.h"
#include "design/dimmer_program.h"
#include "design/illuminance_model.h"
#include "light/luminaire_frame.h"

namespace relight {

namespace {

constexpr double kMetTolerance = 1e-6;      // relative, as the programs' margin
constexpr double kBindingTolerance = 1e-4;  // relative: a target at its bound

// Per free luminaire: W at dimmer 1 from "power_w", else from its IES/LDT file; the others
// the mean of those known, or 1 when none is ("equal").
std::vector<double> luminaire_watts(const RelitScene& relit,
                                    std::span<const LuminaireFreedom> freedom,
                                    std::span<const std::size_t> free, bool& all_known) {
  std::vector<std::optional<double>> known(free.size());
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < free.size(); ++k) {
    const std::size_t j = free[k];
    known[k] = freedom[j].power_w;
    if (!known[k]) known[k] = relit.relighter().distribution(j).input_watts();
    if (known[k]) {
      sum += *known[k];
      ++n;
    }
  }
  all_known = n == free.size();
  const double fallback = n > 0 ? sum / static_cast<double>(n) : 1.0;
  std::vector<double> watts(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) watts[k] = known[k].value_or(fallback);
  return watts;
}

nlohmann::json vec_json(Vec3 v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

// The start document with the free luminaires' settings and, without daylight, dark windows.
nlohmann::json result_document(const Scene& scene, const StartState& start,
                               const LightingState& state, std::span<const std::size_t> free,
                               const std::vector<bool>& aimed, std::span<const double> dimmers,
                               bool daylight) {
  nlohmann::json doc = start.document.is_object() ? start.document : nlohmann::json::object();
  for (std::size_t k = 0; k < free.size(); ++k) {
    const std::size_t j = free[k];
    nlohmann::json& l = doc["luminaires"][state.luminaires[j].name];
    if (!l.is_object()) l = nlohmann::json::object();
    l["on"] = true;
    l["dimmer"] = dimmers[k];
    if (aimed[k]) {
      l.erase("target");
      l["aim"] = vec_json(state.luminaires[j].aim);
      l["c0"] = vec_json(state.luminaires[j].c0);
    }
  }
  if (!daylight) {
    for (const Portal& p : scene.portals) {
      nlohmann::json& entry = doc["portals"][p.name];
      if (!entry.is_object()) entry = nlohmann::json::object();
      entry["tint"] = {0.0, 0.0, 0.0};
    }
  }
  return doc;
}

TargetOutcome outcome(const Target& t, std::span<const double> lux) {
  TargetOutcome o{t, set_value(lux, t.kind)};
  const double scale =
      t.kind == TargetKind::kU0Min ? std::max(t.value, 1e-3) : std::max(t.value, 1.0);
  const double excess = is_lower_bound(t.kind) ? t.value - o.achieved : o.achieved - t.value;
  o.met = excess <= kMetTolerance * scale;
  o.violation = o.met ? 0.0 : excess / scale;
  o.binding = !o.met || std::abs(excess) <= kBindingTolerance * scale;
  return o;
}

void rebase_files(nlohmann::json& node, const std::filesystem::path& from,
                  const std::filesystem::path& to) {
  if (node.is_object()) {
    for (auto& [key, value] : node.items()) {
      if (key == "file" && value.is_string() &&
          std::filesystem::path(value.get<std::string>()).is_relative()) {
        const std::filesystem::path file = (from / value.get<std::string>()).lexically_normal();
        value = std::filesystem::relative(file, to).generic_string();
      } else {
        rebase_files(value, from, to);
      }
    }
  } else if (node.is_array()) {
    for (nlohmann::json& value : node) rebase_files(value, from, to);
  }
}

}  // namespace

OptimizeResult optimize_lighting(RelitScene& relit, const StartState& start,
                                 const DesignTargets& targets, const OptimizeOptions& options) {
  const auto began = std::chrono::steady_clock::now();
  const Scene& scene = relit.scene();
  LightingState state = default_lighting_state(scene);
  apply_lighting_state(state, scene, start.document, start.where, start.dir);
  if (!options.daylight) {
    for (PortalState& p : state.portals) p.tint = {0, 0, 0};
  }

  // The unknowns: every luminaire not fixed (those the start state adds are free, dimmer
  // 0..1); the aimed ones start in their cones.
  std::vector<LuminaireFreedom> freedom = targets.luminaires;
  freedom.resize(state.luminaires.size());
  std::vector<std::size_t> free;
  std::vector<AimCone> cones;
  std::vector<std::size_t> cone_of;  // model index of each cone's luminaire
  std::vector<AimOffset> offsets;
  for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
    const LuminaireFreedom& f = freedom[j];
    if (f.fixed) continue;
    if (f.aim_cone_deg > 0) {
      const AimCone cone{scene.luminaires.at(j).aim, f.aim_cone_deg * kPi / 180};
      LuminaireState& l = state.luminaires[j];
      offsets.push_back(offset_in_cone(cone, l.aim));
      l.aim = aim_in_cone(cone, offsets.back());
      l.c0 = reorthogonalised_c0(l.c0, l.aim);
      cones.push_back(cone);
      cone_of.push_back(free.size());
    }
    free.push_back(j);
  }
  std::vector<std::size_t> sets;
  for (const Target& t : targets.targets) {
    if (std::find(sets.begin(), sets.end(), t.set) == sets.end()) sets.push_back(t.set);
  }

  OptimizeResult result;
  result.objective = targets.objective;
  IlluminanceModel model = illuminance_model(relit, state, free, sets);
  DimmerProblem problem;
  problem.model = &model;
  problem.targets = targets.targets;
  problem.objective = targets.objective;
  for (const std::size_t j : free) {
    problem.lo.push_back(freedom[j].dimmer_lo);
    problem.hi.push_back(freedom[j].dimmer_hi);
  }
  problem.watts = luminaire_watts(relit, freedom, free, result.watts_from_data);
  DimmerSolution best = solve_dimmers(problem);
  int iterations = best.iterations;

  result.aim_trials = search_aims(cones, offsets, [&](std::size_t i, AimOffset offset) {
    const std::size_t k = cone_of[i];
    LuminaireState l = state.luminaires[free[k]];
    l.aim = aim_in_cone(cones[i], offset);
    l.c0 = reorthogonalised_c0(l.c0, l.aim);
    std::vector<double> kept(model.rows());
    for (std::size_t r = 0; r < model.rows(); ++r) kept[r] = model.column(r, k);
    update_model_column(model, relit, state, k, l);
    const DimmerSolution trial = solve_dimmers(problem);
    iterations += trial.iterations;
    if (better_solution(trial, best, targets.objective)) {
      best = trial;
      state.luminaires[free[k]].aim = l.aim;
      state.luminaires[free[k]].c0 = l.c0;
      return true;
    }
    for (std::size_t r = 0; r < model.rows(); ++r) {
      model.columns[r * free.size() + k] = kept[r];
    }
    return false;
  });
  result.iterations = iterations;

  std::vector<bool> aimed(free.size(), false);
  for (const std::size_t k : cone_of) aimed[k] = true;
  result.state = result_document(scene, start, state, free, aimed, best.dimmers, options.daylight);
  result.power_w = best.power_w;

  // What the written document gives, read as `relight probe` reads it.
  LightingState written = default_lighting_state(scene);
  apply_lighting_state(written, scene, result.state, start.where, start.dir);
  relit.apply(written);
  const std::vector<std::vector<double>> lux = sensor_set_lux(relit);
  result.feasible = best.feasible;
  double smallest_u0 = 1;
  for (const Target& t : targets.targets) {
    result.targets.push_back(outcome(t, lux[t.set]));
    result.feasible = result.feasible && result.targets.back().met;
    if ((t.kind == TargetKind::kEmMin || t.kind == TargetKind::kEMin) && t.value > 0) {
      smallest_u0 = std::min(smallest_u0, set_value(lux[t.set], TargetKind::kU0Min));
    }
  }
  std::vector<const TargetOutcome*> bound;
  for (const TargetOutcome& o : result.targets) {
    if (result.feasible ? o.binding : !o.met) bound.push_back(&o);
  }
  std::stable_sort(bound.begin(), bound.end(), [](const TargetOutcome* a, const TargetOutcome* b) {
    return a->violation > b->violation;
  });
  for (const TargetOutcome* o : bound) result.binding.push_back(target_name(scene, o->target));
  result.objective_value =
      targets.objective == DesignObjective::kUniformity ? smallest_u0 : result.power_w;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return result;
}

nlohmann::json optimize_summary(const Scene& scene, const OptimizeResult& r) {
  nlohmann::json targets = nlohmann::json::array();
  for (const TargetOutcome& o : r.targets) {
    targets.push_back({{"set", scene.sensors[o.target.set].name},
                       {"target", target_key(o.target.kind)},
                       {"value", o.target.value},
                       {"achieved", o.achieved},
                       {"met", o.met},
                       {"binding", o.binding}});
  }
  nlohmann::json luminaires = nlohmann::json::object();
  if (const auto lums = r.state.find("luminaires"); lums != r.state.end()) {
    for (const auto& [name, entry] : lums->items()) {
      if (entry.contains("dimmer")) luminaires[name] = entry;
    }
  }
  return {{"feasible", r.feasible},
          {"objective", r.objective_value},
          {"objective_name", r.objective == DesignObjective::kPower ? "power" : "uniformity"},
          {"power_w", r.power_w},
          {"watts_from_data", r.watts_from_data},
          {"iterations", r.iterations},
          {"aim_trials", r.aim_trials},
          {"seconds", r.seconds},
          {"binding", r.binding},
          {"targets", targets},
          {"luminaires", luminaires}};
}

nlohmann::json rebase_relative_files(nlohmann::json document, const std::filesystem::path& from,
                                     const std::filesystem::path& to) {
  namespace fs = std::filesystem;
  if (fs::absolute(from).lexically_normal() == fs::absolute(to).lexically_normal()) return document;
  rebase_files(document, fs::absolute(from), fs::absolute(to));
  return document;
}

}  // namespace relight
