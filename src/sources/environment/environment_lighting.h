// The top-level environment's run-time term (Iwasaki et al., Cyberworlds, §V, Eq. 3: the capture
// paper, papers/003): at every receiver of normal n the product of its binary self-visibility cut
// (sources/environment/self_visibility.h) with the environment's first moments on the direction
// tree (light/environment_clusters.h), summed over the cut's visible nodes,
//     E(x) = Σ_{k visible from x} n · ∫_{cell(k)} L ω dω,
// exact for any environment on nodes whose leaves agree, so a small bright source's shadow is
// as sharp as the leaves' spacing (1.1° at 32,768 directions); then that direct light bounced
// through the precompute's gather operator (engine/runtime_scene.h; the paper shows direct
// light only, and `relight reference --max-bounces 1` compares with set_bounce(false)). The
// environment is clustered and the receivers summed again only when the state's environment
// changes; the bounce starts from the last one. Toward an eye, a glossy receiver reflects
//     L_o = Σ_j f(ω_j, ω_o) · n · M_j
// over its visible nodes split until each lies within a cone of kGlossyNodeDeg (a node of open
// sky would otherwise put a quadrant's light at one direction of a narrow lobe), the nodes of
// the cut finer than that summed into the split node holding them (glossy_nodes.h: one BRDF
// evaluation a 3° node, however finely a shadow's edge or a product of fields cuts it), ω_j
// the direction of the split node's light — its luminance moment's, so that a sun or a lamp in
// a map lands where it is, not at the node's centre — or its mean direction when it holds none.
// The environment's compact sources (light/compact_sources.h: a sky's sun, a map's small bright
// spots) are not in the moments: they are traced at every receiver from its ray point, pushed
// off its surface, against the static scene (sources/environment/compact_light.h), their light
// added to the direct light and bounced with it, and kept apart so that `render --direct pixel`
// traces them per pixel instead (add_block without direct light leaves them out); the
// renderers' glossy shading traces them toward the eye as it traces luminaires.
// Pinned by tests/cli/environment_cuts_test.cpp (against the reference) and
// tests/render/glossy_view_test.cpp (the view's kept diffuse-layer sums).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/light_term.h"
#include "engine/runtime_scene.h"
#include "light/compact_sources.h"
#include "light/environment.h"
#include "light/environment_clusters.h"
#include "math/direction_tree.h"
#include "math/point_grid.h"
#include "scene/environment_spec.h"
#include "sources/environment/cuts_sections.h"
#include "sources/environment/environment_objects.h"
#include "sources/environment/glossy_nodes.h"
#include "sources/objects/object_mesh.h"

namespace relight {

class EnvironmentLighting : public LightTerm {
 public:
  // `runtime` holds the receivers' normals and bounces the direct light (when it has a gather
  // operator); `objects` are the scene's movable objects as prepared (TransferView::objects),
  // whose visibility cut fields `cuts` holds. All must outlive the term.
  EnvironmentLighting(const CutsTransferView& cuts, const RuntimeScene& runtime,
                      std::span<const ObjectMesh> objects = {});

  // Lights the scene by `spec` (none: dark); returns whether the light changed. Loads a map
  // file only when the file differs from the last one's.
  bool set_environment(const std::optional<EnvironmentSpec>& spec);
  std::string_view kind() const override { return "environment"; }
  bool set_state(const LightingState& state) override { return set_environment(state.environment); }
  // Whether the interreflected light is added (the default) or the direct light alone, as
  // `relight reference --max-bounces 1` traces it.
  void set_bounce(bool bounce);
  bool bounces() const { return bounce_; }

  void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const override;
  std::size_t transfer_bytes() const override;
  // The compact sources traced exactly (sources/environment/compact_light.h); the rest of the
  // environment's direct light is the cuts' sum, kept with or without direct light.
  std::unique_ptr<const DirectLights> direct_lights(const Occluders& occluders,
                                                    int opening_samples) const override;

  const DirectionTree& tree() const { return tree_; }
  // ∫ L ω dω per node of the tree for the current environment (light/environment_clusters.h).
  std::span<const RgbMoment> moments() const { return moments_; }
  // The current environment, when there is one.
  const Environment* environment() const { return env_ ? &*env_ : nullptr; }
  // The irradiance the cut of receiver r gives under the current environment (the compact
  // sources left out).
  Rgb irradiance(std::size_t r) const;
  // The current environment's compact sources, traced rather than clustered.
  std::span<const CompactSource> compact_sources() const { return compact_.sources; }
  // Σ_j weight(ω_j) · e_j over the view's nodes of receiver r (glossy_nodes.h: its visible
  // nodes split to kGlossyNodeDeg, and those finer summed into the split node holding them),
  // e_j = n · Σ_{k visible in j} v_k M_k, n its normal, ω_j the direction of node j's light: the
  // outgoing radiance when `weight` is the BRDF toward the eye (the compact sources left out).
  // The visibility v is the receiver's cut times the fields of the movable objects that reach
  // it, as last placed (update_objects), or its own cut where none does.
  template <typename Weight>
  Rgb reflected(std::size_t r, const Weight& weight) const {
    Rgb out{};
    for_each_light(r, [&](const Rgb& e, Vec3 l) { out += e * weight(l); });
    return out;
  }
  // Calls visit(e_j, ω_j) for each of receiver r's view nodes whose light e_j is positive in a
  // channel.
  template <typename Visit>
  void for_each_light(std::size_t r, const Visit& visit) const {
    const Vec3 n = runtime_.normal(r);
    walk_view_nodes([&](const auto& f) { for_each_room_node(r, f); }, moments_,
                    [&](std::uint32_t begin, std::uint32_t end, float v) {
                      for (std::uint32_t i = begin; i < end; ++i) {
                        const std::uint32_t j = glossy_.node[i];
                        const Rgb e = moments_[j].irradiance(n);
                        if (e.r > 0 || e.g > 0 || e.b > 0) visit(e * v, light_direction_[j]);
                      }
                    },
                    [&](std::uint32_t i, const RgbMoment& part) {
                      const Rgb e = part.irradiance(n);
                      if (e.r > 0 || e.g > 0 || e.b > 0)
                        visit(e, light_direction_[glossy_.node[i]]);
                    });
  }
  // The same at object vertex q (PlacedObjects order) as the objects were last placed
  // (update_objects), through its visibility in its object's frame; `weight` takes world
  // directions. 0 without objects or when its object is hidden.
  template <typename Weight>
  Rgb reflected_object(std::size_t q, const PlacedObjects& placed, const Weight& weight) const {
    Rgb out{};
    for_each_object_light(q, placed, [&](const Rgb& e, Vec3 l) { out += e * weight(l); });
    return out;
  }
  // Calls visit(e_j, ω_j) as for_each_light at object vertex q, each node's moments weighted
  // by the vertex's visibility of it, ω_j in the world.
  template <typename Visit>
  void for_each_object_light(std::size_t q, const PlacedObjects& placed, const Visit& visit) const {
    const ValueCut* cut = objects_ ? objects_->object_visibility(q, placed) : nullptr;
    if (cut == nullptr) return;
    const std::size_t a = placed.object_of_vertex(q);
    const std::span<const RgbMoment> m = objects_->object_moments(a);
    const std::span<const Vec3> directions = objects_->object_light_directions(a);
    const Vec3 n = objects_->meshes()[a].normals[q - placed.first_vertex[a]];
    const VerticalTurn turn(objects_->object_turn(a));  // its sine and cosine once
    walk_view_nodes([&](const auto& f) { for_each_value_node(*cut, f); }, m,
                    [&](std::uint32_t begin, std::uint32_t end, float v) {
                      for (std::uint32_t i = begin; i < end; ++i) {
                        const std::uint32_t j = glossy_.node[i];
                        const Rgb e = m[j].irradiance(n);
                        if (e.r > 0 || e.g > 0 || e.b > 0) visit(e * v, turn(directions[j]));
                      }
                    },
                    [&](std::uint32_t i, const RgbMoment& part) {
                      const Rgb e = part.irradiance(n);
                      if (e.r > 0 || e.g > 0 || e.b > 0)
                        visit(e, turn(directions[glossy_.node[i]]));
                    });
  }
  // reflected(r, specular lobe of `brdf`) and reflected_object(q, placed, specular lobe of
  // `brdf`) in single precision, the split's nodes eight at a time (glossy_nodes.h,
  // material/specular_lobe_sum.h): what a view frame evaluates at each glossy vertex. The
  // object's `brdf` is made here in its object's frame from `m`, its normal there and the
  // world's unit direction toward the eye `v`.
  Rgb reflected_specular(std::size_t r, const MetallicRoughnessToward& brdf) const;
  Rgb reflected_object_specular(std::size_t q, const PlacedObjects& placed,
                                const MetallicRoughness& m, Vec3 v) const;
  // What a glossy BRDF's coupled diffuse layer needs of the light at a vertex, whatever the
  // viewer (material/metallic_roughness.h, diffuse_of_sums): over the nodes above the BRDF's
  // normal n, Σ e_j, Σ e_j A(n·ω_j) and Σ e_j B(n·ω_j) at one roughness.
  struct DiffuseLayerSums {
    Rgb e, a, b;
  };
  // Receiver r's (object vertex q's) sums, as the objects were last placed, for normal n and
  // `roughness`, kept until the light, a placement or the roughness changes:
  // a view frame then evaluates only the specular lobe at each node. Not const: calls for
  // distinct vertices may run at once, not two for one vertex. The view cache's storage is
  // made by prepare_view_cache, which must come first.
  const DiffuseLayerSums& diffuse_layer(std::size_t r, Vec3 n, double roughness);
  const DiffuseLayerSums& object_diffuse_layer(std::size_t q, const PlacedObjects& placed, Vec3 n,
                                               double roughness);
  void prepare_view_cache(std::size_t object_vertices);
  static constexpr double kGlossyNodeDeg = 3;
  // With movable objects: their shadows at the room's receivers and the direct light at their
  // vertices for the objects as placed (sources/environment/environment_objects.h), made again when
  // the environment or a placement changed since the last call.
  void update_objects(const PlacedObjects& placed, std::span<const MovablePlacement> placements);
  // What the objects take from the room's direct light (3 per receiver) and their vertices'
  // direct light (3 per object vertex), the compact sources' parts apart (the renderers that
  // trace direct light per pixel trace those); empty without objects.
  std::span<const float> object_room_delta() const {
    return objects_ ? objects_->room_delta() : std::span<const float>{};
  }
  std::span<const float> object_direct() const {
    return objects_ ? objects_->object_direct() : std::span<const float>{};
  }
  std::span<const float> object_room_compact() const {
    return objects_ ? objects_->room_compact() : std::span<const float>{};
  }
  std::span<const float> object_compact() const {
    return objects_ ? objects_->object_compact() : std::span<const float>{};
  }
  double objects_seconds() const { return objects_ ? objects_->seconds() : 0.0; }
  std::size_t objects_kept_turns() const { return objects_ ? objects_->kept_turns() : 0; }

  // Wall time of the last update: the cluster values and the receivers' sums, and the bounce.
  double seconds() const { return seconds_; }
  double bounce_seconds() const { return bounce_seconds_; }

 private:
  // Clusters the current environment, sums the receivers and bounces their light.
  void relight();
  // A cut's visible nodes in the view's split (glossy_nodes.h): for_each_visible(f) calls
  // f(node, value) for each visible node in leaf order. Calls whole(begin, end, value) for each
  // run of split nodes glossy_.node[begin, end) seen whole at one value, and part(i, Σ value ·
  // moments[k]) for split node glossy_.node[i] seen through nodes k finer than it.
  template <typename ForEachVisible, typename Whole, typename Part>
  void walk_view_nodes(const ForEachVisible& for_each_visible, std::span<const RgbMoment> moments,
                       const Whole& whole, const Part& part) const {
    constexpr std::uint32_t kNone = GlossyNodes::kNone;
    std::uint32_t begin = 0, end = 0, held = kNone;
    float value = 0;
    // The held split node's Σ value · moments, as RgbMoment's channels (locals, so that they
    // stay in registers across the walk).
    float r0 = 0, r1 = 0, r2 = 0, g0 = 0, g1 = 0, g2 = 0, b0 = 0, b1 = 0, b2 = 0;
    const auto flush = [&] {
      RgbMoment sum;
      sum.r[0] = r0, sum.r[1] = r1, sum.r[2] = r2;
      sum.g[0] = g0, sum.g[1] = g1, sum.g[2] = g2;
      sum.b[0] = b0, sum.b[1] = b1, sum.b[2] = b2;
      part(held, sum);
      r0 = r1 = r2 = g0 = g1 = g2 = b0 = b1 = b2 = 0;
    };
    for_each_visible([&](std::uint32_t node, float v) {
      // A node finer than the split is summed into the split node holding it (a holder's
      // nodes come one after another in leaf order).
      const std::uint32_t in = glossy_.within[node];
      if (in != kNone) {
        if (in != held) {
          if (held != kNone) flush();
          held = in;
        }
        const RgbMoment& m = moments[node];
        r0 += v * m.r[0], r1 += v * m.r[1], r2 += v * m.r[2];
        g0 += v * m.g[0], g1 += v * m.g[1], g2 += v * m.g[2];
        b0 += v * m.b[0], b1 += v * m.b[1], b2 += v * m.b[2];
        return;
      }
      const std::uint32_t first = glossy_.first[node];
      if (first != end || v != value) {
        if (end > begin) whole(begin, end, value);
        begin = first;
        value = v;
      }
      end = glossy_.last[node];
    });
    if (held != kNone) flush();
    if (end > begin) whole(begin, end, value);
  }
  // Calls f(node, value) for each node of a visibility cut seen at all.
  template <typename F>
  void for_each_value_node(const ValueCut& cut, const F& f) const {
    for_each_node(cut, static_cast<std::uint32_t>(tree_.leaf_count()),
                  [&](std::uint32_t node, float v) {
                    if (v > 0) f(node, v);
                  });
  }
  // The same for room receiver r with the objects as last placed: the product of its cut and
  // the fields of the objects that reach it, or its own cut where none does.
  template <typename F>
  void for_each_room_node(std::size_t r, const F& f) const {
    if (const ValueCut* cut = objects_ ? objects_->room_visibility(r) : nullptr) {
      for_each_value_node(*cut, f);
      return;
    }
    cuts_.self_visibility.for_each_visible(r, [&](std::uint32_t node, int) { f(node, 1.0f); });
  }

  CutsTransferView cuts_;
  const RuntimeScene& runtime_;
  std::size_t receivers_;
  DirectionTree tree_;
  PointGrid leaves_;
  std::optional<EnvironmentSpec> spec_;
  std::optional<Environment> env_;
  std::shared_ptr<const EquirectMap> map_;  // the last map read, and its file
  std::filesystem::path map_file_;
  std::vector<RgbMoment> moments_;
  EnvironmentGridParts grid_parts_;    // the environment's grid placed in the world, kept
  std::vector<Vec3> light_direction_;  // per node: moment_direction (light/environment_clusters.h)
  GlossyNodes glossy_;                 // the tree split to kGlossyNodeDeg
  GlossyLights room_glossy_;           // the split's lights in the world
  std::vector<GlossyLights> object_glossy_;  // in each object's frame, as last placed
  bool bounce_ = true, warm_ = false;
  CompactSources compact_;
  std::vector<float> compact_fraction_;   // per receiver, per compact source: f_s
  std::vector<float> compact_direct_;     // 3 per receiver: the compact sources' part of direct_
  std::vector<float> direct_, indirect_;  // 3 per receiver
  std::optional<EnvironmentObjects> objects_;
  bool objects_stale_ = true;  // the environment changed since the objects' last update
  // The view's diffuse-layer sums per receiver and per object vertex, each with the roughness
  // and the generation (the environment's and the placements') it was made for.
  struct KeptDiffuseLayer {
    DiffuseLayerSums sums;
    double roughness = -1;
    std::uint64_t generation = 0;
  };
  template <typename ForEachLight>
  static const DiffuseLayerSums& keep_diffuse_layer(KeptDiffuseLayer& kept,
                                                    std::uint64_t generation, Vec3 n,
                                                    double roughness, const ForEachLight& for_each);
  std::vector<KeptDiffuseLayer> room_layer_, object_layer_;
  // Made again with the environment or a placement (update, update_objects).
  std::uint64_t generation_ = 1;
  double seconds_ = 0, bounce_seconds_ = 0;
};

}  // namespace relight
