#include "sources/luminaires/luminaire_lighting.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "light/luminaire_frame.h"
#include "math/sh.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {

namespace {

bool same_distribution(const DistributionSpec& a, const DistributionSpec& b) {
  return a.type == b.type && a.candela == b.candela && a.exponent == b.exponent &&
         a.cutoff_deg == b.cutoff_deg && a.gamma_deg == b.gamma_deg &&
         a.curve_candela == b.curve_candela && a.file == b.file;
}

// The one control point in which two curves of equal length differ, or -1.
int single_moved_point(const DistributionSpec& a, const DistributionSpec& b) {
  if (a.type != DistributionType::kCurve || b.type != DistributionType::kCurve ||
      a.gamma_deg.size() != b.gamma_deg.size()) {
    return -1;
  }
  int moved = -1;
  for (std::size_t i = 0; i < a.gamma_deg.size(); ++i) {
    if (a.gamma_deg[i] != b.gamma_deg[i] || a.curve_candela[i] != b.curve_candela[i]) {
      if (moved >= 0) return -1;
      moved = static_cast<int>(i);
    }
  }
  return moved;
}

// The luminaires of one state through their openings, shadowed by `occluders`.
class LuminaireDirectLights : public DirectLights {
 public:
  LuminaireDirectLights(const Occluders& occluders, std::vector<LuminaireLight> lights,
                        std::span<const LuminaireState> states)
      : occluders_(occluders), lights_(std::move(lights)), states_(states) {
    openings_.reserve(lights_.size());
    for (std::size_t j = 0; j < lights_.size(); ++j) {
      openings_.push_back(
          luminaire_opening(scene_luminaire(states_[j]), lights_[j].distribution->opening()));
    }
  }
  Rgb irradiance_at(Vec3 p, Vec3 n) const override {
    return luminaire_direct_irradiance(occluders_, lights_, p, n);
  }
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance,
                   const SeenLightVisit& visit) const override {
    for (std::size_t j = 0; j < lights_.size(); ++j) {
      visit(LightKind::kLuminaire, states_[j].name,
            luminaire_seen_from(occluders_, lights_[j], openings_[j], p, n, with_luminance));
    }
  }

 private:
  Occluders occluders_;
  std::vector<LuminaireLight> lights_;
  std::span<const LuminaireState> states_;
  std::vector<LuminousOpening> openings_;  // per luminaire (luminaire_opening)
};

bool same_opening(const LuminaireState& a, const LuminaireState& b) {
  return a.has_size == b.has_size && a.size == b.size;
}

}  // namespace

LuminaireLighting::LuminaireLighting(LuminaireTransferSet transfer, const Scene& scene,
                                     ShWindow window)
    : transfer_(transfer), window_(window) {
  if (transfer_.luminaires.size() != scene.luminaires.size()) {
    throw std::invalid_argument("LuminaireLighting: transfer and scene disagree on luminaires");
  }
  luminaires_.resize(scene.luminaires.size());
  specs_ = scene.luminaires;
  for (const Luminaire& l : scene.luminaires) states_.push_back(luminaire_state(l));
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    luminaires_[j].stored = j;
    project_distribution(j, states_[j]);
    apply(j, states_[j], true);
  }
}

std::vector<LuminaireLight> LuminaireLighting::lights(int opening_samples) const {
  std::vector<LuminaireLight> out;
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    const LuminaireState& s = states_[j];
    const Distribution& d = luminaires_[j].distribution;
    LuminaireLight l{
        s.position, photometric_frame(s.aim, s.c0), s.on ? s.color * s.dimmer : Rgb{}, &d, {}};
    l.opening = opening_sample_offsets(luminaire_opening(scene_luminaire(s), d.opening()), l.frame,
                                       opening_samples);
    out.push_back(std::move(l));
  }
  return out;
}

bool LuminaireLighting::is_moved(std::size_t j, const LuminaireState& s) const {
  return j >= specs_.size() || length(s.position - specs_[j].position) > 1e-9 ||
         s.has_size != specs_[j].has_size || (s.has_size && !(s.size == specs_[j].size));
}

bool LuminaireLighting::needs_runtime(std::span<const LuminaireState> states) const {
  for (std::size_t j = 0; j < states.size(); ++j) {
    if (is_moved(j, states[j])) return true;
  }
  return false;
}

LuminaireLighting::Geometry LuminaireLighting::geometry(std::size_t j) const {
  const Lit& l = luminaires_[j];
  if (l.live) {
    return {l.geometry.dir_x, l.geometry.dir_y, l.geometry.dir_z, l.geometry.factor};
  }
  const LuminaireTransferView& v = transfer_.luminaires[j];
  return {v.dir_x, v.dir_y, v.dir_z, v.factor};
}

// A moved or added luminaire's geometry, traced from every receiver as the precompute traces a
// stored one's; its interreflection stands in from the nearest stored luminaire until bounced.
void LuminaireLighting::trace_live(std::size_t j, const LuminaireState& s) {
  if (runtime_ == nullptr || !runtime_->can_bounce()) {
    // The Relighter refuses such a state first, naming the file (runtime/relighter.h).
    throw std::logic_error(
        "LuminaireLighting: a moved luminaire needs a run-time scene that bounces");
  }
  const auto start = std::chrono::steady_clock::now();
  Lit& l = luminaires_[j];
  const Distribution& distribution = l.distribution;  // loaded for s by project_distribution
  const std::vector<Vec3> offsets =
      opening_sample_offsets(luminaire_opening(scene_luminaire(s), distribution.opening()),
                             photometric_frame(s.aim, s.c0), kOpeningSamples);
  l.geometry = compute_direct_geometry(runtime_->receiver_set(), runtime_->ray_points(),
                                       runtime_->occluders(), s.position, offsets, false);
  l.live = true;
  l.bounced = false;
  l.mirror_traced = false;
  l.stored.reset();
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const double d = length(specs_[i].position - s.position);
    if (d < nearest) {
      nearest = d;
      l.stored = i;
    }
  }
  trace_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool LuminaireLighting::set_state(std::span<const LuminaireState> states) {
  if (states.size() < specs_.size()) {
    throw std::invalid_argument("LuminaireLighting: one state per luminaire of the scene");
  }
  trace_seconds_ = 0;
  const bool added = states.size() > luminaires_.size();
  if (added) {
    luminaires_.resize(states.size());
    states_.resize(states.size());
    for (std::size_t j = specs_.size(); j < states.size(); ++j) {
      states_[j] = states[j];
      project_distribution(j, states[j]);
      trace_live(j, states[j]);
      apply(j, states[j], true);
    }
  }
  bool changed = added;
  for (std::size_t j = 0; j < states.size(); ++j) {
    const LuminaireState& now = states_[j];
    const LuminaireState& next = states[j];
    const bool moved = !(now.position == next.position) || !same_opening(now, next);
    const bool photometry_changed = !(now.aim == next.aim) || !(now.c0 == next.c0) ||
                                    !same_distribution(now.distribution, next.distribution);
    // A move keeps the SH weights: only a new aim or distribution is projected (and its file
    // read) again.
    if (photometry_changed) project_distribution(j, next);
    if (moved) {
      if (is_moved(j, next)) {
        trace_live(j, next);
      } else {  // back where the precompute hung it: its stored transfer again
        luminaires_[j].live = false;
        luminaires_[j].geometry = {};
        luminaires_[j].indirect.clear();
        luminaires_[j].stored = j;
        luminaires_[j].mirror_traced = false;
      }
    } else if (photometry_changed && luminaires_[j].live) {
      luminaires_[j].bounced = false;  // its direct light changed: bounce it again
    }
    apply(j, next, moved || photometry_changed);
    changed = changed || moved || photometry_changed || now.on != next.on ||
              now.dimmer != next.dimmer || !(now.color == next.color);
    states_[j] = next;
  }
  // Luminaires a state no longer adds are gone from the light.
  if (states.size() < luminaires_.size()) {
    luminaires_.resize(states.size());
    states_.resize(states.size());
    changed = true;
  }
  return changed;
}

bool LuminaireLighting::update() {
  bounce_seconds_ = 0;
  if (!bounce_live_) return false;
  bool bounced = false;
  const std::size_t n = transfer_.receivers;
  for (Lit& l : luminaires_) {
    if (!l.live || l.bounced || !l.active) continue;
    // Per unit colour: the same scalar direct light in every channel; each channel bounces
    // with its own albedo.
    scratch_.resize(3 * n);
    for (std::size_t r = 0; r < n; ++r) {
      scratch_[3 * r] = scratch_[3 * r + 1] = scratch_[3 * r + 2] = l.direct[r];
    }
    const bool warm = l.indirect.size() == 3 * n;
    l.indirect.resize(3 * n);
    bounce_seconds_ += runtime_->bounce(scratch_, l.indirect, warm);
    l.bounced = true;
    bounced = true;
  }
  return bounced;
}

bool LuminaireLighting::converged() const {
  for (const Lit& l : luminaires_) {
    if (l.active && l.live && !l.bounced) return false;
  }
  return true;
}

std::size_t LuminaireLighting::live_count() const {
  std::size_t n = 0;
  for (const Lit& l : luminaires_) n += l.live ? 1 : 0;
  return n;
}

void LuminaireLighting::project_distribution(std::size_t j, const LuminaireState& s) {
  Lit& l = luminaires_[j];
  const LuminaireShSettings sh_settings{transfer_.sh_order, window_};
  l.distribution = load_distribution(s.distribution);
  if (s.distribution.type != DistributionType::kCurve) {
    l.curve.reset();
    l.sh = luminaire_world_sh(l.distribution, s.aim, s.c0, sh_settings);
    return;
  }
  // Curves: when one control point moved, update the Legendre weights by Eq. 21 (only the
  // samples next to the point change); otherwise build the projector anew.
  const int moved = l.curve ? single_moved_point(states_[j].distribution, s.distribution) : -1;
  bool incremental = false;
  if (moved >= 0) {
    try {
      const auto k = static_cast<std::size_t>(moved);
      move_curve_point(*l.curve, moved, radians(s.distribution.gamma_deg[k]),
                       s.distribution.curve_candela[k]);
      incremental = true;
      ++incremental_curve_updates_;
    } catch (const std::exception&) {
      // A move the projector cannot take (e.g. past a neighbour): project anew below.
    }
  }
  const bool unchanged = l.curve && same_distribution(states_[j].distribution, s.distribution);
  if (!incremental && !unchanged) {  // a re-aimed curve keeps its projector
    l.curve = make_curve_projector(std::get<CurveModel>(l.distribution.model), sh_settings);
  }
  l.sh.resize(static_cast<std::size_t>(sh_count(transfer_.sh_order)));
  curve_world_sh(*l.curve, s.aim, l.sh);
}

void LuminaireLighting::apply(std::size_t j, const LuminaireState& s, bool direct_changed) {
  Lit& l = luminaires_[j];
  const int k = sh_count(transfer_.sh_order);
  if (direct_changed) {
    if (!transfer_.direct_sh_mode || l.live) {
      // Exact direct: the current distribution evaluated toward every receiver.
      const Geometry v = geometry(j);
      const PhotometricFrame frame = photometric_frame(s.aim, s.c0);
      l.direct.resize(transfer_.receivers);
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, transfer_.receivers), [&](const auto& range) {
            for (std::size_t r = range.begin(); r != range.end(); ++r) {
              if (v.factor[r] == 0) {
                l.direct[r] = 0;
                continue;
              }
              const Vec3 w{v.dir_x[r], v.dir_y[r], v.dir_z[r]};
              l.direct[r] = static_cast<float>(l.distribution.intensity(frame.to_photometric(w)) *
                                               v.factor[r]);
            }
          });
      respond_glossy(j, s);
    }
  }
  const Rgb rgb = s.on ? s.color * s.dimmer : Rgb{};
  l.rgb[0] = static_cast<float>(rgb.r);
  l.rgb[1] = static_cast<float>(rgb.g);
  l.rgb[2] = static_cast<float>(rgb.b);
  l.active = s.on && max_component(rgb) > 0;
  l.weights.resize(3 * static_cast<std::size_t>(k));
  for (int b = 0; b < k; ++b) {
    for (int c = 0; c < 3; ++c) {
      l.weights[3 * static_cast<std::size_t>(b) + static_cast<std::size_t>(c)] =
          static_cast<float>(l.sh[static_cast<std::size_t>(b)] * l.rgb[c]);
    }
  }
}

void LuminaireLighting::add_block(std::size_t b, bool include_direct,
                                  float (&acc)[3][kBlock]) const {
  const std::size_t n = transfer_.receivers;
  const auto k = static_cast<std::size_t>(sh_count(transfer_.sh_order));
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    const Lit& l = luminaires_[j];
    if (!l.active) continue;
    if (!include_direct) {
      // interreflected light only
    } else if (transfer_.direct_sh_mode && !l.live) {
      const float* s = transfer_.luminaires[j].direct_sh.data() + b * k * kBlock;
      for (std::size_t basis = 0; basis < k; ++basis) {
        const float* t = s + basis * kBlock;
        for (int c = 0; c < 3; ++c) {
          const float w = l.weights[3 * basis + c];
          for (std::size_t i = 0; i < kBlock; ++i) acc[c][i] += w * t[i];
        }
      }
    } else {
      const float* d = l.direct.data() + base;
      for (int c = 0; c < 3; ++c) {
        for (std::size_t i = 0; i < count; ++i) acc[c][i] += l.rgb[c] * d[i];
      }
    }
    if (l.live && l.bounced) {
      const float* e = l.indirect.data() + 3 * base;
      for (int c = 0; c < 3; ++c) {
        for (std::size_t i = 0; i < count; ++i) acc[c][i] += l.rgb[c] * e[3 * i + c];
      }
    } else if (l.stored) {
      add_weighted_block(transfer_.luminaires[*l.stored].indirect, b, k, l.weights.data(), acc);
    }
  }
}

void LuminaireLighting::add_glossy(std::span<float> out) const {
  if (glossy_ == nullptr) return;
  for (const Lit& l : luminaires_) {
    if (!l.active || l.glossy.empty()) continue;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), std::size_t{3 * 4096}),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          out[i] += l.rgb[i % 3] * l.glossy[i];
                        }
                      });
  }
}

void LuminaireLighting::set_glossy(const GlossyFirstBounce* glossy) {
  const GlossyFirstBounce* now =
      glossy != nullptr && !glossy->empty() && !transfer_.direct_sh_mode ? glossy : nullptr;
  if (now == glossy_ && now == nullptr) return;
  glossy_ = now;
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    luminaires_[j].mirror_traced = false;
    respond_glossy(j, states_[j]);
  }
}

void LuminaireLighting::respond_glossy(std::size_t j, const LuminaireState& s) {
  Lit& l = luminaires_[j];
  if (glossy_ == nullptr) {
    l.glossy.clear();
    l.mirror_paths.clear();
    l.mirror_traced = false;
    return;
  }
  const Geometry v = geometry(j);
  l.glossy.resize(3 * transfer_.receivers);
  // D': what the stored transfer reflected at the glossy vertices — the distribution's SH
  // series toward each (its weights are l.sh), times the same geometry.
  std::vector<float> reflected(transfer_.receivers, 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, transfer_.receivers),
                    [&](const auto& range) {
                      for (std::size_t r = range.begin(); r != range.end(); ++r) {
                        if (!glossy_->glossy(r) || v.factor[r] == 0) continue;
                        const Vec3 w{v.dir_x[r], v.dir_y[r], v.dir_z[r]};
                        reflected[r] = static_cast<float>(sh_evaluate(l.sh, w) * v.factor[r]);
                      }
                    });
  const MirrorReflection* mirrors = glossy_->mirrors();
  if (mirrors == nullptr) {
    glossy_->respond(v.dir_x, v.dir_y, v.dir_z, l.direct, l.glossy, nullptr, reflected);
    return;
  }
  // Its image in the near-mirror planes: the paths traced once, I evaluated as aimed now.
  if (!l.mirror_traced) {
    l.mirror_paths = mirrors->trace(s.position);
    l.mirror_traced = true;
  }
  const PhotometricFrame frame = photometric_frame(s.aim, s.c0);
  std::vector<float> intensity(l.mirror_paths.size());
  for (std::size_t k = 0; k < intensity.size(); ++k) {
    const float* e = l.mirror_paths[k].emit;
    intensity[k] =
        static_cast<float>(l.distribution.intensity(frame.to_photometric({e[0], e[1], e[2]})));
  }
  const MirrorLight mirror{l.mirror_paths, intensity};
  glossy_->respond(v.dir_x, v.dir_y, v.dir_z, l.direct, l.glossy, &mirror, reflected);
}

std::unique_ptr<const DirectLights> LuminaireLighting::direct_lights(const Occluders& occluders,
                                                                     int opening_samples) const {
  return std::make_unique<LuminaireDirectLights>(occluders, lights(opening_samples), states_);
}

std::size_t LuminaireLighting::transfer_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    const Lit& l = luminaires_[j];
    if (!l.active) continue;
    if (l.live && l.bounced) {
      bytes += l.indirect.size() * sizeof(float);
    } else if (l.stored) {
      bytes += transfer_.luminaires[*l.stored].indirect.size_bytes();
    }
    bytes += transfer_.direct_sh_mode && !l.live ? transfer_.luminaires[j].direct_sh.size_bytes()
                                                 : l.direct.size() * sizeof(float);
    bytes += l.glossy.size() * sizeof(float);
  }
  return bytes;
}

}  // namespace relight
