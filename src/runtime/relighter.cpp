#include "runtime/relighter.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/transfer_blocks.h"

namespace relight {

namespace {

std::optional<RuntimeScene> make_runtime_scene(const TransferView& transfer, const Scene& scene) {
  if (scene.portals.empty() && scene.emitters.empty() && scene.objects.empty()) return std::nullopt;
  BounceSettings bounce;
  bounce.tolerance = scene.precompute.tolerance;
  bounce.max_bounces = scene.precompute.max_bounces;
  return std::optional<RuntimeScene>(std::in_place, transfer.scene, bounce);
}

}  // namespace

Relighter::Relighter(TransferView transfer, const Scene& scene, RelighterSettings settings)
    : transfer_(std::move(transfer)),
      luminaire_specs_(scene.luminaires),
      runtime_(make_runtime_scene(transfer_, scene)),
      luminaires_(
          {transfer_.luminaires, transfer_.receivers, transfer_.sh_order, transfer_.direct_sh_mode},
          scene, settings.window),
      portals_({transfer_.portals, transfer_.receivers, transfer_.portal_sh_order},
               runtime_ ? &*runtime_ : nullptr, scene),
      state_(default_lighting_state(scene)) {
  terms_.push_back({&luminaires_, {}});
  terms_.push_back({&portals_, {}});
  if (!scene.emitters.empty()) {
    emitters_.emplace(transfer_.nearfield, *runtime_, scene, settings.emitters);
    terms_.push_back({&*emitters_, {}});
  }
  for (Term& term : terms_) {
    for (PartialSum& sum : term.sums) sum.values.assign(3 * transfer_.receivers, 0.0f);
  }
  if (!scene.objects.empty()) {
    if (!runtime_->can_bounce()) {
      throw std::invalid_argument(
          "Relighter: a scene with movable objects needs the gather operator in its transfer "
          "(run relight precompute again)");
    }
    if (transfer_.objects.size() != scene.objects.size()) {
      throw std::invalid_argument("Relighter: the transfer's objects are not the scene's");
    }
    objects_.emplace(*runtime_, transfer_.objects);
    room_light_.assign(3 * transfer_.receivers, 0.0f);
  }
}

void Relighter::set_state(const LightingState& state) {
  const bool changed[3] = {luminaires_.set_state(state.luminaires),
                           portals_.set_state(state.portals),
                           emitters_ && emitters_->set_state(state.emitters)};
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    if (changed[t]) terms_[t].sums[0].valid = terms_[t].sums[1].valid = false;
  }
  if (objects_ && objects_->set_state(state.objects)) objects_dirty_ = true;
  state_ = state;
}

// Points on a luminous opening for the objects' shadows at sensors (vertices take 16).
constexpr int kSensorOpeningSamples = 256;

void Relighter::update_objects() {
  // E0 with direct light, summed again when a term's state changed.
  const bool light_changed = sum_terms(1, room_light_);
  if (!light_changed && !objects_dirty_) return;
  const std::vector<LuminaireLight> lights = luminaires_.lights(luminaire_specs_);
  const std::vector<LuminaireLight> sensor_lights =
      luminaires_.lights(luminaire_specs_, kSensorOpeningSamples);
  ObjectLightInputs in{room_light_, lights, sensor_lights, portals_.suns(), std::nullopt,
                       nullptr,     {}};
  if (!portals_.suns().empty()) in.sun_geometry.emplace(portals_.sun_geometry());
  if (emitters_) in.emitters = &emitters_->placed();
  if (portals_.size() > 0) {
    in.glass = [this](std::uint32_t p, Vec3 direction) {
      return portals_.portal(p).shell.radiance(direction);
    };
  }
  objects_->update(in, light_changed);
  objects_dirty_ = false;
}

void Relighter::relight(std::span<float> out, bool include_direct) {
  const std::size_t n = transfer_.receivers;
  if (out.size() != 3 * n) throw std::invalid_argument("Relighter: output size mismatch");
  if (emitters_) emitters_->update();  // its sampling and bounce, if its state changed
  if (!objects_) {
    sum_terms(include_direct ? 1 : 0, out);
    return;
  }
  update_objects();
  if (include_direct) {
    std::copy(room_light_.begin(), room_light_.end(), out.begin());
  } else {
    sum_terms(0, out);
  }
  objects_->add_to_room(out, include_direct);
}

bool Relighter::sum_terms(std::size_t slot, std::span<float> out) {
  const std::size_t n = transfer_.receivers;
  // Each kind of source keeps its own sum (per direct mode), recomputed only after a change
  // to it: a frame in which only the sky moves reads the portals' transfer, not the
  // luminaires', and the other way round.
  std::array<bool, 3> redo{};
  bool any = false;
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    redo[t] = !terms_[t].sums[slot].valid;
    any = any || redo[t];
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, block_count(n)), [&](const auto& blocks) {
    for (std::size_t b = blocks.begin(); b != blocks.end(); ++b) {
      const std::size_t base = b * kBlock;
      const std::size_t count = std::min(kBlock, n - base);
      for (std::size_t t = 0; t < terms_.size(); ++t) {
        if (!redo[t]) continue;
        alignas(64) float acc[3][kBlock] = {};
        terms_[t].source->add_block(b, slot == 1, acc);
        std::vector<float>& sum = terms_[t].sums[slot].values;
        for (std::size_t i = 0; i < count; ++i) {
          for (std::size_t c = 0; c < 3; ++c) sum[3 * (base + i) + c] = acc[c][i];
        }
      }
      // out = Σ over terms of their sums, one streaming pass per term over the block.
      const std::size_t lo = 3 * base, hi = 3 * (base + count);
      const float* first = terms_.front().sums[slot].values.data();
      for (std::size_t i = lo; i < hi; ++i) out[i] = first[i];
      for (std::size_t t = 1; t < terms_.size(); ++t) {
        const float* v = terms_[t].sums[slot].values.data();
        for (std::size_t i = lo; i < hi; ++i) out[i] += v[i];
      }
    }
  });
  std::size_t bytes = 3 * n * sizeof(float);  // the output written
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    terms_[t].sums[slot].valid = true;
    // Every sum read; those redone, their transfer read and the sum written.
    bytes += 3 * n * sizeof(float);
    if (redo[t]) bytes += terms_[t].source->transfer_bytes() + 3 * n * sizeof(float);
  }
  last_frame_bytes_ = bytes;
  return any;
}

std::size_t Relighter::transfer_bytes() const {
  std::size_t bytes = 0;
  for (const Term& term : terms_) bytes += term.source->transfer_bytes();
  return bytes;
}

}  // namespace relight
