#include "sources/emitters/emitter_lighting.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/sh.h"
#include "sources/emitters/emitter_direct.h"

namespace relight {

namespace {

// The emitters of one state as placed, shadowed by `occluders`.
class EmitterDirectLights : public DirectLights {
 public:
  EmitterDirectLights(const Occluders& occluders, const PlacedEmitters& placed,
                      std::span<const Emitter> emitters, int visibility_samples)
      : occluders_(occluders),
        placed_(placed),
        emitters_(emitters),
        visibility_samples_(visibility_samples) {}
  Rgb irradiance_at(Vec3 p, Vec3 n) const override {
    return emitter_direct_irradiance(placed_, &occluders_, p, n, visibility_samples_);
  }
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance,
                   const SeenLightVisit& visit) const override {
    for (std::size_t k = 0; k < emitters_.size(); ++k) {
      visit(LightKind::kEmitter, emitters_[k].name,
            emitter_seen_from(placed_, k, &occluders_, p, n, with_luminance, visibility_samples_));
    }
  }

 private:
  Occluders occluders_;
  PlacedEmitters placed_;
  std::span<const Emitter> emitters_;
  int visibility_samples_;
};

}  // namespace

EmitterLighting::EmitterLighting(const NearfieldTransferView& transfer, const RuntimeScene& runtime,
                                 const Scene& scene, EmitterLightingSettings settings)
    : transfer_(&transfer),
      runtime_(&runtime),
      scene_(&scene),
      settings_(settings),
      nearfield_(runtime.receiver_positions(), transfer.sh_order),
      bounces_(runtime.can_bounce() && scene.precompute.nearfield_interreflection) {
  if (transfer.sh_order < 1 || scene.emitters.empty()) {
    throw std::invalid_argument("EmitterLighting: the scene has no emitters");
  }
  const std::size_t n = runtime.receivers();
  const auto k = static_cast<std::size_t>(sh_count(transfer.sh_order));
  if (transfer.transfer.size() != n * k) {
    throw std::invalid_argument("EmitterLighting: transfer and receivers disagree");
  }
  for (const Emitter& e : scene.emitters) states_.push_back(emitter_state(e));
  placed_ = place_emitters(scene_->emitters, states_);
}

bool EmitterLighting::set_state(std::span<const EmitterState> states) {
  if (states.size() != states_.size()) {
    throw std::invalid_argument("EmitterLighting: one state per emitter");
  }
  if (std::equal(states.begin(), states.end(), states_.begin())) return !current_;
  states_.assign(states.begin(), states.end());
  placed_ = place_emitters(scene_->emitters, states_);
  current_ = false;
  return true;
}

std::unique_ptr<const DirectLights> EmitterLighting::direct_lights(const Occluders& occluders,
                                                                   int opening_samples) const {
  return std::make_unique<EmitterDirectLights>(occluders, placed_, scene_->emitters,
                                               opening_samples);
}

bool EmitterLighting::update() {
  if (current_) return false;
  relight();
  current_ = true;
  return true;
}

void EmitterLighting::relight() {
  NearfieldSettings s;
  s.method = NearfieldMethod::kAdaptive;
  s.epsilon = settings_.epsilon;
  s.max_samples = settings_.max_samples;
  s.face_size = settings_.face_size;
  sampling_ = nearfield_.light(placed_, s);
  const std::size_t n = runtime_->receivers();
  const auto k = static_cast<std::size_t>(sh_count(transfer_->sh_order));
  // The direct light: Sun 2005's reconstruction at vertices, the exact integral at sensors.
  std::vector<float> direct(3 * n);
  nearfield_irradiance(transfer_->transfer, sampling_.sh, k, direct);
  const Occluders room(runtime_->occluders());
  const Occluders* occluders = &room;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(runtime_->vertex_count(), n), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r) {
          const Rgb e =
              emitter_direct_irradiance(placed_, occluders, runtime_->ray_point(r),
                                        runtime_->normal(r), settings_.visibility_samples);
          direct[3 * r] = static_cast<float>(e.r);
          direct[3 * r + 1] = static_cast<float>(e.g);
          direct[3 * r + 2] = static_cast<float>(e.b);
        }
      });
  // An emitter moved a little starts its bounce from the last solution.
  const bool warm = indirect_.size() == 3 * n;
  indirect_.resize(3 * n, 0.0f);
  bounce_seconds_ = 0;
  if (bounces_) {
    // What bounces is the exact direct light at the vertices too: the SH reconstruction at
    // l < 4 of an emitter half a metre away misplaces its light enough to make the ceiling
    // above a downward panel 12 % too bright (tests/cli/emitter_probe_test.cpp). A vertex's
    // value is the mean of the exact light over its hat function (engine/runtime_scene.h).
    std::vector<float> reflected(3 * n);
    runtime_->hat_means(
        [&](Vec3 p, Vec3 normal) {
          return emitter_direct_irradiance(placed_, occluders, p, normal,
                                           settings_.bounce_visibility_samples);
        },
        settings_.hat_subdivision, reflected);
    bounce_seconds_ = runtime_->bounce(reflected, indirect_, warm);
  }
  total_.resize(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) total_[i] = direct[i] + indirect_[i];
}

void EmitterLighting::add_block(std::size_t block, bool include_direct,
                                float (&acc)[3][kBlock]) const {
  const std::vector<float>& e = include_direct ? total_ : indirect_;
  const std::size_t n = e.size() / 3;
  const std::size_t base = block * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t c = 0; c < 3; ++c) acc[c][i] += e[3 * (base + i) + c];
  }
}

std::size_t EmitterLighting::transfer_bytes() const {
  return total_.size() * sizeof(float);
}

}  // namespace relight
