#include "sources/environment/environment_lighting.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/input_error.h"
#include "light/environment_clusters.h"
#include "light/environment_map_io.h"
#include "material/metallic_roughness.h"
#include "math/rgb.h"
#include "sources/environment/compact_light.h"

namespace relight {

EnvironmentLighting::EnvironmentLighting(const CutsTransferView& cuts, const RuntimeScene& runtime,
                                         std::span<const ObjectMesh> objects)
    : cuts_(cuts),
      runtime_(runtime),
      receivers_(runtime.receivers()),
      tree_(direction_tree_over_leaves(cuts.directions)),
      leaves_(leaf_grid(tree_)),
      glossy_(glossy_nodes(tree_, std::cos(kGlossyNodeDeg * kPi / 180))),
      compact_direct_(3 * receivers_, 0.0f),
      direct_(3 * receivers_, 0.0f),
      indirect_(3 * receivers_, 0.0f) {
  if (cuts_.self_visibility.cut_count() != receivers_) {
    throw std::invalid_argument("EnvironmentLighting: not one cut per receiver");
  }
  if (!objects.empty()) {
    if (cuts_.fields.size() != objects.size()) {
      throw std::invalid_argument("EnvironmentLighting: not one visibility cut field per object");
    }
    objects_.emplace(cuts_, tree_, leaves_, runtime_, objects);
    object_glossy_.resize(objects.size());
  }
  relight();  // dark until an environment is set: every moment 0
}

namespace {

// The environment's compact sources (its sun, a map's small bright spots), shadowed by
// `occluders`, each from the point pushed off its surface.
class CompactDirectLights : public DirectLights {
 public:
  CompactDirectLights(const Occluders& occluders, std::span<const CompactSource> sources)
      : occluders_(occluders), sources_(sources) {}
  Rgb irradiance_at(Vec3 p, Vec3 n) const override {
    return compact_irradiance(occluders_, sources_, offset_from_surface(p, n), n);
  }
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance,
                   const SeenLightVisit& visit) const override {
    const Vec3 origin = offset_from_surface(p, n);
    for (const CompactSource& source : sources_) {
      visit(LightKind::kEnvironment, std::string_view(),
            compact_seen_from(occluders_, source, origin, n, with_luminance));
    }
  }

 private:
  Occluders occluders_;
  std::span<const CompactSource> sources_;
};

}  // namespace

std::unique_ptr<const DirectLights> EnvironmentLighting::direct_lights(
    const Occluders& occluders, int /*opening_samples*/) const {
  return std::make_unique<CompactDirectLights>(occluders, compact_.sources);
}

bool EnvironmentLighting::set_environment(const std::optional<EnvironmentSpec>& spec) {
  if (spec == spec_ && (env_.has_value() || !spec)) return false;
  if (!spec) {
    env_.reset();
  } else {
    try {
      if (spec->type == EnvironmentType::kMap) {
        if (!map_ || map_file_ != spec->file) {
          map_ = std::make_shared<const EquirectMap>(read_environment_map(spec->file));
          map_file_ = spec->file;
        }
        env_ = make_environment(*spec, map_);
      } else {
        env_ = make_environment(*spec);
      }
    } catch (const std::invalid_argument& e) {
      fail_input(spec->where, e.what());
    }
  }
  spec_ = spec;
  relight();
  return true;
}

void EnvironmentLighting::set_bounce(bool bounce) {
  if (bounce == bounce_) return;
  bounce_ = bounce;
  relight();
}

Rgb EnvironmentLighting::irradiance(std::size_t r) const {
  RgbMoment sum;
  cuts_.self_visibility.for_each_visible(
      r, [&](std::uint32_t node, int) { sum.add(moments_[node], 1); });
  return sum.irradiance(runtime_.normal(r));
}

void EnvironmentLighting::update_objects(const PlacedObjects& placed,
                                         std::span<const MovablePlacement> placements) {
  if (!objects_) return;
  const bool changed =
      objects_->update(env_ ? &*env_ : nullptr, moments_, light_direction_, direct_,
                       RoomCompact{compact_, compact_fraction_, compact_direct_}, placed,
                       placements, objects_stale_);
  objects_stale_ = false;
  // A state that changed no placement (a material edit) keeps the view's sums.
  if (!changed) return;
  ++generation_;
  for (std::size_t a = 0; a < object_glossy_.size(); ++a) {
    object_glossy_[a].fill(glossy_, objects_->object_moments(a),
                           objects_->object_light_directions(a));
  }
}

Rgb EnvironmentLighting::reflected_specular(std::size_t r,
                                            const MetallicRoughnessToward& brdf) const {
  SpecularLobeSum sum(brdf);
  const MomentLightPlanes planes = room_glossy_.planes();
  walk_view_nodes([&](const auto& f) { for_each_room_node(r, f); }, moments_,
                  [&](std::uint32_t begin, std::uint32_t end, float value) {
                    sum.add(planes, begin, end, value);
                  },
                  [&](std::uint32_t i, const RgbMoment& part) {
                    sum.add_one(moment_floats(part), light_direction_[glossy_.node[i]]);
                  });
  return sum.total();
}

Rgb EnvironmentLighting::reflected_object_specular(std::size_t q, const PlacedObjects& placed,
                                                   const MetallicRoughness& m, Vec3 v) const {
  const ValueCut* cut = objects_ ? objects_->object_visibility(q, placed) : nullptr;
  if (cut == nullptr) return {};
  const std::size_t a = placed.object_of_vertex(q);
  const std::span<const Vec3> directions = objects_->object_light_directions(a);
  const Vec3 n = objects_->meshes()[a].normals[q - placed.first_vertex[a]];
  SpecularLobeSum sum(
      MetallicRoughnessToward(m, n, VerticalTurn(objects_->object_turn(a)).inverse(v)));
  const MomentLightPlanes planes = object_glossy_[a].planes();
  walk_view_nodes([&](const auto& f) { for_each_value_node(*cut, f); }, objects_->object_moments(a),
                  [&](std::uint32_t begin, std::uint32_t end, float value) {
                    sum.add(planes, begin, end, value);
                  },
                  [&](std::uint32_t i, const RgbMoment& part) {
                    sum.add_one(moment_floats(part), directions[glossy_.node[i]]);
                  });
  return sum.total();
}

void EnvironmentLighting::prepare_view_cache(std::size_t object_vertices) {
  room_layer_.resize(receivers_);
  object_layer_.resize(object_vertices);
}

template <typename ForEachLight>
const EnvironmentLighting::DiffuseLayerSums& EnvironmentLighting::keep_diffuse_layer(
    KeptDiffuseLayer& kept, std::uint64_t generation, Vec3 n, double roughness,
    const ForEachLight& for_each) {
  if (kept.generation == generation && kept.roughness == roughness) return kept.sums;
  DiffuseLayerSums sums;
  for_each([&](const Rgb& e, Vec3 l) {
    const double n_dot_l = dot(n, l);
    if (n_dot_l <= 0) return;
    const auto [a, b] = specular_albedo_split(n_dot_l, roughness);
    sums.e += e;
    sums.a += e * a;
    sums.b += e * b;
  });
  kept = {sums, roughness, generation};
  return kept.sums;
}

const EnvironmentLighting::DiffuseLayerSums& EnvironmentLighting::diffuse_layer(std::size_t r,
                                                                                Vec3 n,
                                                                                double roughness) {
  return keep_diffuse_layer(room_layer_.at(r), generation_, n, roughness,
                            [&](const auto& visit) { for_each_light(r, visit); });
}

const EnvironmentLighting::DiffuseLayerSums& EnvironmentLighting::object_diffuse_layer(
    std::size_t q, const PlacedObjects& placed, Vec3 n, double roughness) {
  return keep_diffuse_layer(object_layer_.at(q), generation_, n, roughness,
                            [&](const auto& visit) { for_each_object_light(q, placed, visit); });
}

void EnvironmentLighting::relight() {
  const auto start = std::chrono::steady_clock::now();
  objects_stale_ = true;
  ++generation_;
  if (env_) {
    compact_ = find_compact_sources(*env_);
    moments_ = environment_moments(*env_, tree_, leaves_, 0, &compact_, &grid_parts_);
  } else {
    compact_ = {};
    moments_.assign(2 * tree_.leaf_count(), RgbMoment{});
  }
  const std::size_t sources = compact_.sources.size();
  compact_fraction_.assign(sources * receivers_, 0.0f);
  const Occluders room(runtime_.occluders());
  light_direction_ = moment_directions(moments_, tree_);
  room_glossy_.fill(glossy_, moments_, light_direction_);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, receivers_, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r < range.end(); ++r) {
      const Vec3 n = runtime_.normal(r), origin = offset_from_surface(runtime_.ray_point(r), n);
      // Each source's fraction kept for the objects (sources below the surface stay 0).
      const Rgb traced = disc_irradiance(
          std::span<const CompactSource>(compact_.sources), n, [&](const CompactSource& s) {
            const double f = compact_fraction(room, s, origin);
            const auto k = static_cast<std::size_t>(&s - compact_.sources.data());
            compact_fraction_[r * sources + k] = static_cast<float>(f);
            return f;
          });
      store_rgb(irradiance(r) + traced, &direct_[3 * r]);
      store_rgb(traced, &compact_direct_[3 * r]);
    }
  });
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bounce_seconds_ = 0;
  if (bounce_ && env_ && runtime_.can_bounce()) {
    bounce_seconds_ = runtime_.bounce(direct_, indirect_, warm_);
    warm_ = true;
  } else {
    std::fill(indirect_.begin(), indirect_.end(), 0.0f);
    warm_ = false;
  }
}

void EnvironmentLighting::add_block(std::size_t b, bool include_direct,
                                    float (&acc)[3][kBlock]) const {
  // The cuts' direct part in both slots (no renderer evaluates it per pixel); the compact
  // sources' only with direct light.
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, receivers_ - base);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t r = 3 * (base + i);
    for (std::size_t c = 0; c < 3; ++c) {
      acc[c][i] +=
          direct_[r + c] + indirect_[r + c] - (include_direct ? 0 : compact_direct_[r + c]);
    }
  }
}

std::size_t EnvironmentLighting::transfer_bytes() const {
  return 2 * direct_.size() * sizeof(float);
}

}  // namespace relight
