#include "runtime/relighter.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/sh.h"
#include "runtime/luminaire_sh.h"
#include "transfer/transfer_blocks.h"

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

// acc_c[i] += Σ_k w[3k + c] · T[k][c][i] over one block of RGB transfer in the blocked layout
// (transfer/transfer_blocks.h): K bases, each three channels of kBlock receivers.
void add_weighted_block(const float* t, std::size_t k, const std::vector<float>& w,
                        float (&acc)[3][kBlock]) {
  for (std::size_t basis = 0; basis < k; ++basis) {
    for (int c = 0; c < 3; ++c) {
      const float weight = w[3 * basis + c];
      const float* tc = t + (3 * basis + c) * kBlock;
      for (std::size_t i = 0; i < kBlock; ++i) acc[c][i] += weight * tc[i];
    }
  }
}

}  // namespace

Relighter::Relighter(TransferView transfer, const Scene& scene, RelighterSettings settings)
    : transfer_(std::move(transfer)), scene_(&scene), settings_(std::move(settings)) {
  if (transfer_.luminaires.size() != scene.luminaires.size() ||
      transfer_.portals.size() != scene.portals.size()) {
    throw std::invalid_argument("Relighter: transfer and scene disagree on luminaires or portals");
  }
  luminaires_.resize(scene.luminaires.size());
  state_ = default_lighting_state(scene);
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    update_luminaire(j, state_.luminaires[j], true);
  }
  for (PartialSum* sum :
       {&luminaire_sums_[0], &luminaire_sums_[1], &portal_sums_[0], &portal_sums_[1]}) {
    sum->values.assign(3 * transfer_.receivers, 0.0f);
  }
  portals_.resize(scene.portals.size());
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    update_portal_lighting(portals_[p], transfer_.portals[p], transfer_.portal_sh_order,
                           state_.portals[p], scene, settings_.load_environment);
  }
}

void Relighter::set_state(const LightingState& state) {
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    const LuminaireState& now = state_.luminaires[j];
    const LuminaireState& next = state.luminaires.at(j);
    const bool geometry_changed = !(now.aim == next.aim) || !(now.c0 == next.c0) ||
                                  !same_distribution(now.distribution, next.distribution);
    update_luminaire(j, next, geometry_changed);
    if (geometry_changed || now.on != next.on || now.dimmer != next.dimmer ||
        !(now.color == next.color)) {
      luminaire_sums_[0].valid = luminaire_sums_[1].valid = false;
    }
  }
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (state.portals.at(p) == state_.portals[p]) continue;
    update_portal_lighting(portals_[p], transfer_.portals[p], transfer_.portal_sh_order,
                           state.portals[p], *scene_, settings_.load_environment);
    portal_sums_[0].valid = portal_sums_[1].valid = false;
  }
  state_ = state;
}

void Relighter::project_distribution(std::size_t j, const LuminaireState& s) {
  Luminaire& l = luminaires_[j];
  const LuminaireShSettings sh_settings{transfer_.sh_order, settings_.window};
  l.distribution = load_distribution(s.distribution);
  if (s.distribution.type != DistributionType::kCurve) {
    l.curve.reset();
    l.sh = luminaire_world_sh(l.distribution, s.aim, s.c0, sh_settings);
    return;
  }
  // Curves: when one control point moved, update the Legendre weights by Eq. 21 (only the
  // samples next to the point change); otherwise build the projector anew.
  const int moved =
      l.curve ? single_moved_point(state_.luminaires[j].distribution, s.distribution) : -1;
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
  const bool unchanged =
      l.curve && same_distribution(state_.luminaires[j].distribution, s.distribution);
  if (!incremental && !unchanged) {  // a re-aimed curve keeps its projector
    l.curve = make_curve_projector(std::get<CurveModel>(l.distribution.model), sh_settings);
  }
  l.sh.resize(static_cast<std::size_t>(sh_count(transfer_.sh_order)));
  curve_world_sh(*l.curve, s.aim, l.sh);
}

void Relighter::update_luminaire(std::size_t j, const LuminaireState& s, bool geometry_changed) {
  Luminaire& l = luminaires_[j];
  const int k = sh_count(transfer_.sh_order);
  if (geometry_changed) {
    project_distribution(j, s);
    if (!transfer_.direct_sh_mode) {
      // Exact direct: the current distribution evaluated toward every receiver.
      const LuminaireTransferView& v = transfer_.luminaires[j];
      const Vec3 c90 = cross(s.c0, s.aim);
      l.direct.resize(transfer_.receivers);
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, transfer_.receivers), [&](const auto& range) {
            for (std::size_t r = range.begin(); r != range.end(); ++r) {
              if (v.factor[r] == 0) {
                l.direct[r] = 0;
                continue;
              }
              const Vec3 w{v.dir_x[r], v.dir_y[r], v.dir_z[r]};
              const Vec3 local{dot(w, s.c0), dot(w, c90), dot(w, s.aim)};
              l.direct[r] = static_cast<float>(l.distribution.intensity(local) * v.factor[r]);
            }
          });
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
  if (transfer_.direct_sh_mode) l.direct_weights = l.weights;
}

void Relighter::add_luminaires(std::size_t b, bool include_direct, float (&acc)[3][kBlock]) const {
  const std::size_t n = transfer_.receivers;
  const auto k = static_cast<std::size_t>(sh_count(transfer_.sh_order));
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    const Luminaire& l = luminaires_[j];
    if (!l.active) continue;
    const LuminaireTransferView& v = transfer_.luminaires[j];
    if (!include_direct) {
      // interreflected light only
    } else if (transfer_.direct_sh_mode) {
      const float* s = v.direct_sh.data() + b * k * kBlock;
      for (std::size_t basis = 0; basis < k; ++basis) {
        const float* t = s + basis * kBlock;
        for (int c = 0; c < 3; ++c) {
          const float w = l.direct_weights[3 * basis + c];
          for (std::size_t i = 0; i < kBlock; ++i) acc[c][i] += w * t[i];
        }
      }
    } else {
      const float* d = l.direct.data() + base;
      for (int c = 0; c < 3; ++c) {
        for (std::size_t i = 0; i < count; ++i) acc[c][i] += l.rgb[c] * d[i];
      }
    }
    add_weighted_block(v.indirect.data() + b * k * 3 * kBlock, k, l.weights, acc);
  }
}

void Relighter::add_portals(std::size_t b, bool include_direct, float (&acc)[3][kBlock]) const {
  const std::size_t n = transfer_.receivers;
  const auto kp = static_cast<std::size_t>(sh_count(transfer_.portal_sh_order));
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    const PortalLighting& l = portals_[p];
    if (!l.active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    const ShellCubemap& shell = include_direct || !l.sharp_sun ? l.cubemap : l.sky_cubemap;
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint64_t at = v.offsets[base + i];
      const Rgb e =
          dot_receiver_cubemap(v.records.subspan(at, v.offsets[base + i + 1] - at), shell);
      acc[0][i] += static_cast<float>(e.r);
      acc[1][i] += static_cast<float>(e.g);
      acc[2][i] += static_cast<float>(e.b);
    }
    add_weighted_block(v.indirect.data() + b * kp * 3 * kBlock, kp, l.weights, acc);
  }
}

void Relighter::relight(std::span<float> out, bool include_direct) {
  const std::size_t n = transfer_.receivers;
  if (out.size() != 3 * n) throw std::invalid_argument("Relighter: output size mismatch");
  // Each kind of source keeps its own sum (per direct mode), recomputed only after a change
  // to it: a frame in which only the sky moves reads the portals' transfer, not the
  // luminaires', and the other way round.
  const std::size_t slot = include_direct ? 1 : 0;
  PartialSum& lum = luminaire_sums_[slot];
  PartialSum& por = portal_sums_[slot];
  const bool redo_lum = !lum.valid, redo_por = !por.valid;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block_count(n)), [&](const auto& blocks) {
    for (std::size_t b = blocks.begin(); b != blocks.end(); ++b) {
      const std::size_t base = b * kBlock;
      const std::size_t count = std::min(kBlock, n - base);
      const auto store = [&](PartialSum& sum, const float(&acc)[3][kBlock]) {
        for (std::size_t i = 0; i < count; ++i) {
          for (int c = 0; c < 3; ++c) sum.values[3 * (base + i) + c] = acc[c][i];
        }
      };
      if (redo_lum) {
        alignas(64) float acc[3][kBlock] = {};
        add_luminaires(b, include_direct, acc);
        store(lum, acc);
      }
      if (redo_por) {
        alignas(64) float acc[3][kBlock] = {};
        add_portals(b, include_direct, acc);
        store(por, acc);
      }
      for (std::size_t i = 3 * base; i < 3 * (base + count); ++i) {
        out[i] = lum.values[i] + por.values[i];
      }
    }
  });
  lum.valid = por.valid = true;
  last_frame_bytes_ = (redo_lum ? luminaire_bytes() : 0) + (redo_por ? portal_bytes() : 0) +
                      (2 + std::size_t{redo_lum} + std::size_t{redo_por} + 1) * 3 * n *
                          sizeof(float);  // the sums read, those redone written, out written
}

std::size_t Relighter::luminaire_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t j = 0; j < luminaires_.size(); ++j) {
    if (!luminaires_[j].active) continue;
    const LuminaireTransferView& v = transfer_.luminaires[j];
    bytes += v.indirect.size_bytes();
    bytes += transfer_.direct_sh_mode ? v.direct_sh.size_bytes()
                                      : luminaires_[j].direct.size() * sizeof(float);
  }
  return bytes;
}

std::size_t Relighter::portal_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (!portals_[p].active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    bytes += v.indirect.size_bytes() + v.records.size_bytes() + v.offsets.size_bytes();
  }
  return bytes;
}

std::size_t Relighter::transfer_bytes() const {
  return luminaire_bytes() + portal_bytes();
}

}  // namespace relight
