#include "runtime/relighter.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/input_error.h"
#include "engine/transfer_blocks.h"
#include "material/material_reflectance.h"

namespace relight {

namespace {

BounceSettings bounce_settings(const Scene& scene) {
  BounceSettings bounce;
  bounce.tolerance = scene.precompute.tolerance;
  bounce.max_bounces = scene.precompute.max_bounces;
  return bounce;
}

// Whether relight() may compute the sensor rows alone (RelighterSettings::sensors_only): the
// suns' bounce needs the gather operator, and movable objects and glossy surfaces light the
// sensors through the whole room's light.
bool can_read_sensors_only(const TransferView& transfer, const Scene& scene) {
  return !transfer.scene.gather_rows.empty() && scene.objects.empty() &&
         glossy_materials(scene.materials).empty();
}

std::optional<RuntimeScene> make_runtime_scene(const TransferView& transfer, const Scene& scene,
                                               bool sensors_only,
                                               std::shared_ptr<const SensorImportance> solved) {
  if (scene.portals.empty() && scene.emitters.empty() && scene.objects.empty() &&
      !scene.environment &&
      (glossy_materials(scene.materials).empty() || transfer.scene.gather_rows.empty())) {
    return std::nullopt;
  }
  std::optional<RuntimeScene> runtime(std::in_place, transfer.scene, bounce_settings(scene));
  if (sensors_only && !scene.portals.empty()) runtime->solve_sensor_importance(std::move(solved));
  return runtime;
}

SunBounce sun_bounce(const RelighterSettings& settings, bool sensors_only) {
  if (sensors_only) return SunBounce::kSensors;
  return settings.warm_sun_bounce ? SunBounce::kWarm : SunBounce::kCold;
}

LightTermSettings light_term_settings(const RelighterSettings& settings, SunBounce sun_bounce) {
  return {settings.window, settings.emitters, sun_bounce, settings.environment_bounce};
}

}  // namespace

Relighter::Relighter(TransferView transfer, const Scene& scene, const RelighterSettings& settings)
    : transfer_(std::move(transfer)),
      runtime_(make_runtime_scene(transfer_, scene,
                                  settings.sensors_only && can_read_sensors_only(transfer_, scene),
                                  settings.sensor_importance)),
      lights_(transfer_, runtime_ ? &*runtime_ : nullptr, scene,
              light_term_settings(
                  settings, sun_bounce(settings, runtime_ && runtime_->has_sensor_importance()))),
      state_(default_lighting_state(scene)),
      bounce_(bounce_settings(scene)),
      vertex_albedo_(transfer_.scene.vertex_albedo),
      warm_sun_bounce_(settings.warm_sun_bounce),
      sensors_only_(settings.sensors_only && can_read_sensors_only(transfer_, scene)) {
  if (runtime_) lights_.luminaires().set_runtime(&*runtime_);
  make_glossy_bounce(scene.materials, transfer_.scene.vertex_albedo);
  for (LightTerm* light : lights_.all()) {
    terms_.push_back({light, {}});
    for (PartialSum& sum : terms_.back().sums) sum.values.assign(3 * transfer_.receivers, 0.0f);
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
    objects_->set_direct_only(!settings.environment_bounce);
    objects_->set_materials(scene.materials);
    room_light_.assign(3 * transfer_.receivers, 0.0f);
  }
}

void Relighter::set_glossy(const GlossyFirstBounce* glossy) {
  for (LightTerm* light : lights_.all()) light->set_glossy(glossy);
}

void Relighter::invalidate(const LightTerm* source) {
  for (Term& term : terms_) {
    if (term.source == source) term.sums[0].valid = term.sums[1].valid = false;
  }
}

void Relighter::make_glossy_bounce(std::span<const Material> materials,
                                   std::span<const float> albedo) {
  glossy_stale_ = false;
  const std::vector<std::uint32_t>& material_of = transfer_.scene.vertex_material;
  GlossyMaterials glossy = glossy_materials(materials);
  if (glossy.empty() || !runtime_ || !runtime_->can_bounce() || material_of.empty()) {
    set_glossy(nullptr);
    glossy_bounce_.reset();
    mirrors_.reset();
    return;
  }
  std::vector<std::int32_t> glossy_of(material_of.size(), -1);
  const std::span<const float> texture = transfer_.scene.vertex_texture;
  for (std::size_t v = 0; v < material_of.size(); ++v) {
    if (material_of[v] == kNoMaterial) continue;
    glossy_of[v] = glossy.index.at(material_of[v]);
    // A textured glossy vertex reflects by its own BRDF: the base colour times its texture.
    const Rgb t = vertex_texture_at(texture, v);
    if (glossy_of[v] >= 0 && t != Rgb{1, 1, 1}) {
      MetallicRoughness own = glossy.brdf[static_cast<std::size_t>(glossy_of[v])];
      own.albedo = own.albedo * t;
      glossy_of[v] = static_cast<std::int32_t>(glossy.brdf.size());
      glossy.brdf.push_back(own);
    }
  }
  // Made in place: the terms keep their pointer and relight once, with the new one (and
  // none, should making it fail).
  const Receivers& receivers = runtime_->receiver_set();
  try {
    mirrors_.emplace(*runtime_, glossy_of, glossy.brdf);
    glossy_bounce_.emplace(runtime_->gather(), receivers.positions, receivers.normals,
                           std::move(glossy_of), std::move(glossy.brdf), albedo, bounce_,
                           &*mirrors_);
  } catch (...) {
    set_glossy(nullptr);
    throw;
  }
  set_glossy(&*glossy_bounce_);
}

void Relighter::add_glossy(std::span<float> out) const {
  for (const LightTerm* light : lights_.all()) light->add_glossy(out);
}

void Relighter::set_state(const LightingState& state) {
  if (lights_.luminaires().needs_runtime(state.luminaires)) {
    // A moved or added luminaire is traced against the room and bounced through its stored
    // gather operator.
    if (transfer_.scene.gather_rows.empty()) {
      fail_input("luminaires",
                 "moving or adding a luminaire needs the gather operator, which this transfer "
                 "file does not keep (\"runtime_bounce\": false): precompute again without it");
    }
    if (!runtime_) {
      runtime_.emplace(transfer_.scene, bounce_);
      lights_.luminaires().set_runtime(&*runtime_);
    }
  }
  for (LightTerm* light : lights_.all()) {
    if (light->set_state(state)) invalidate(light);
  }
  if (objects_ && objects_->set_state(state.objects)) objects_dirty_ = true;
  // A state made without materials (LightingState{} filled by hand) keeps the scene's.
  const std::vector<Material> materials =
      state.materials.empty() ? state_.materials : state.materials;
  set_materials(materials);
  state_ = state;
  state_.materials = materials;
}

void Relighter::set_environment_bounce(bool bounce) {
  EnvironmentLighting* environment = lights_.environment();
  if (environment == nullptr) return;
  environment->set_bounce(bounce);
  invalidate(environment);
}

void Relighter::set_materials(const std::vector<Material>& materials) {
  if (materials.size() != state_.materials.size()) {
    throw std::invalid_argument("Relighter: the state's materials are not the scene's");
  }
  if (materials == state_.materials) return;
  // An edit lights the sensors through the whole room's light: every row from now on.
  if (sensors_only_) {
    sensors_only_ = false;
    lights_.portals().set_sun_bounce(warm_sun_bounce_ ? SunBounce::kWarm : SunBounce::kCold);
    for (Term& term : terms_) term.sums[0].valid = term.sums[1].valid = false;
  }
  const std::vector<std::uint32_t>& material_of = transfer_.scene.vertex_material;
  // Files written before live material edits: the state asks what the file cannot do.
  if (material_of.empty()) {
    fail_input("the state's materials",
               "this transfer file does not record the vertices' materials, which live material "
               "edits need (run relight precompute again)");
  }
  // The vertices' albedo under the edited materials; a vertex no triangle uses keeps its own.
  const std::span<const float> stored = transfer_.scene.vertex_albedo;
  const std::span<const float> texture = transfer_.scene.vertex_texture;
  for (std::size_t v = 0; v < material_of.size(); ++v) {
    const Rgb a = material_of[v] == kNoMaterial
                      ? Rgb{stored[3 * v], stored[3 * v + 1], stored[3 * v + 2]}
                      : bounce_albedo(materials.at(material_of[v]), vertex_texture_at(texture, v));
    vertex_albedo_[3 * v] = static_cast<float>(a.r);
    vertex_albedo_[3 * v + 1] = static_cast<float>(a.g);
    vertex_albedo_[3 * v + 2] = static_cast<float>(a.b);
  }
  if (!albedo_edit_) {
    if (transfer_.scene.gather_rows.empty()) {
      fail_input("the state's materials",
                 "live material edits need the gather operator, which this transfer file does "
                 "not keep (run relight precompute again)");
    }
    if (!runtime_) {
      runtime_.emplace(transfer_.scene, bounce_);
      lights_.luminaires().set_runtime(&*runtime_);
    }
    albedo_edit_.emplace(runtime_->gather(), stored, bounce_);
    edit_total_.assign(3 * transfer_.receivers, 0.0f);
    edit_delta_.assign(3 * transfer_.receivers, 0.0f);
  }
  albedo_edit_->set_albedo(vertex_albedo_);
  edit_dirty_ = true;
  // The glossy surfaces' first bounce as edited: reflected by the edited BRDFs, less what the
  // edited albedo reflects diffusely, bounced by the edited room (engine/glossy_first_bounce.h).
  // An approximate frame keeps the last one (the edited BRDFs reflect as their diffuse
  // stand-in meanwhile); the converged frame makes it (relight()).
  if (!glossy_materials(materials).empty() || glossy_bounce_) {
    if (material_bounces_ >= 0) {
      glossy_stale_ = true;
    } else {
      make_glossy_bounce(materials, vertex_albedo_);
    }
    glossy_dirty_ = true;
  }
  if (objects_) {
    objects_->set_albedo(vertex_albedo_, materials);
    objects_dirty_ = true;
  }
}

// Points on a luminous opening for the objects' shadows at sensors (vertices take 16).
constexpr int kSensorOpeningSamples = 256;

bool Relighter::sum_edited(std::span<float> total) {
  bool changed = sum_terms(1, total);
  if (!albedo_edit_) return changed;
  // A converged edit needs solving again after the light or the edit changed, or after an
  // approximate frame; an approximate one only after a change.
  const bool approximate = material_bounces_ >= 0;
  if (changed || edit_dirty_ || (!approximate && !edit_final_)) {
    // After a converged solve X starts from it (a dragged colour slider, a dimmer moved).
    albedo_edit_->solve(total, edit_delta_, material_bounces_, edit_solved_ && edit_final_);
    edit_solved_ = true;
    edit_final_ = !approximate || !albedo_edit_->active();
    edit_dirty_ = false;
    changed = true;
  }
  for (std::size_t i = 0; i < total.size(); ++i) total[i] += edit_delta_[i];
  return changed;
}

void Relighter::update_objects() {
  // E0 with direct light, summed again when a term's state changed.
  const bool light_changed = sum_edited(room_light_) || glossy_dirty_;
  add_glossy(room_light_);
  glossy_dirty_ = false;
  if (!light_changed && !objects_dirty_) return;
  const PortalSetLighting& portals = lights_.portals();
  const std::vector<LuminaireLight> lights = lights_.luminaires().lights();
  const std::vector<LuminaireLight> sensor_lights =
      lights_.luminaires().lights(kSensorOpeningSamples);
  ObjectLightInputs in{
      room_light_, lights, sensor_lights, portals.suns(), std::nullopt, nullptr, {}, {}, {},
      {},          {}};
  if (!portals.suns().empty()) in.sun_geometry.emplace(portals.sun_geometry());
  if (EnvironmentLighting* environment = lights_.environment(); environment != nullptr) {
    // The environment's light on and around the objects as placed, through the cuts.
    environment->update_objects(objects_->placed(), state_.objects);
    in.extra_room = environment->object_room_delta();
    in.extra_objects = environment->object_direct();
    in.traced_room = environment->object_room_compact();
    in.traced_objects = environment->object_compact();
  }
  if (const EmitterLighting* emitters = lights_.emitters(); emitters != nullptr) {
    in.emitters = &emitters->placed();
  }
  if (portals.size() > 0) {
    in.glass = [&portals](std::uint32_t p, Vec3 direction) {
      return portals.portal(p).shell.radiance(direction);
    };
  }
  objects_->update(in, light_changed);
  objects_dirty_ = false;
}

void Relighter::relight(std::span<float> out, bool include_direct) {
  const std::size_t n = transfer_.receivers;
  if (out.size() != 3 * n) throw std::invalid_argument("Relighter: output size mismatch");
  if (glossy_stale_ && material_bounces_ < 0) {
    // A material edit's first frame kept the glossy first bounce from before it: now the
    // edited one.
    make_glossy_bounce(state_.materials, vertex_albedo_);
    glossy_dirty_ = true;
  }
  for (LightTerm* light : lights_.all()) {  // a sampling or bounce left for now
    if (light->update()) invalidate(light);
  }
  if (!objects_) {
    if (!albedo_edit_) {
      sum_terms(include_direct ? 1 : 0, out);
    } else if (include_direct) {
      sum_edited(out);
    } else {
      sum_edited(edit_total_);
      sum_terms(0, out);
      for (std::size_t i = 0; i < out.size(); ++i) out[i] += edit_delta_[i];
    }
    add_glossy(out);
    glossy_dirty_ = false;
    return;
  }
  update_objects();
  if (include_direct) {
    std::copy(room_light_.begin(), room_light_.end(), out.begin());
  } else {
    sum_terms(0, out);
    if (albedo_edit_) {
      for (std::size_t i = 0; i < out.size(); ++i) out[i] += edit_delta_[i];
    }
    add_glossy(out);
  }
  objects_->add_to_room(out, include_direct);
}

void Relighter::sum_block(std::size_t b, std::size_t slot, const std::array<bool, kMaxTerms>& redo,
                          std::span<float> out) {
  const std::size_t n = transfer_.receivers;
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

bool Relighter::sum_terms(std::size_t slot, std::span<float> out) {
  const std::size_t n = transfer_.receivers;
  // Each kind of source keeps its own sum (per direct mode), recomputed only after a change
  // to it: a frame in which only the sky moves reads the portals' transfer, not the
  // luminaires', and the other way round.
  std::array<bool, kMaxTerms> redo{};
  bool any = false;
  for (std::size_t t = 0; t < terms_.size(); ++t) {
    redo[t] = !terms_[t].sums[slot].valid;
    any = any || redo[t];
  }
  // Only the sensors read: the blocks from the one holding the first sensor row.
  const std::size_t first_block = sensors_only_ ? transfer_.scene.vertex_count / kBlock : 0;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first_block, block_count(n)),
                    [&](const auto& blocks) {
                      for (std::size_t b = blocks.begin(); b != blocks.end(); ++b) {
                        sum_block(b, slot, redo, out);
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
