#include "sources/portals/portal_lighting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/input_error.h"
#include "light/environment_map_io.h"
#include "math/placement.h"
#include "math/sh.h"

namespace relight {

std::vector<ExteriorObject> placed_exterior(const Scene& scene,
                                            const std::vector<ExteriorPlacement>& placements) {
  std::vector<ExteriorObject> objects;
  for (std::size_t i = 0; i < scene.exterior.size(); ++i) {
    const ExteriorGeometry& g = scene.exterior[i];
    const ExteriorPlacement p = i < placements.size() ? placements[i] : ExteriorPlacement{};
    if (!p.visible) continue;
    std::vector<Vec3> positions;
    positions.reserve(g.geometry.positions.size());
    for (const Vec3& x : g.geometry.positions) {
      positions.push_back(placed_point(x, g.pivot, p));
    }
    std::map<std::uint32_t, std::size_t> by_material;
    for (std::size_t t = 0; t < g.geometry.triangles.size(); ++t) {
      const std::uint32_t m = g.geometry.triangle_material[t];
      auto it = by_material.find(m);
      if (it == by_material.end()) {
        it = by_material.emplace(m, objects.size()).first;
        objects.push_back({positions, {}, scene.materials.at(m).albedo});
      }
      objects[it->second].triangles.push_back(g.geometry.triangles[t]);
    }
  }
  return objects;
}

namespace {

// The exterior objects as one ray tracer (null when there are none).
std::shared_ptr<const RayTracer> exterior_tracer(const std::vector<ExteriorObject>& objects) {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (const ExteriorObject& o : objects) {
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), o.positions.begin(), o.positions.end());
    for (const Triangle& t : o.triangles)
      triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  if (triangles.empty()) return nullptr;
  return std::make_shared<const RayTracer>(positions, triangles, sequential_ids(triangles.size()));
}

// Bouncing to the sensors needs their importance solved (RuntimeScene::solve_sensor_importance).
void check_sun_bounce(const RuntimeScene* runtime, SunBounce sun_bounce) {
  if (sun_bounce == SunBounce::kSensors && runtime != nullptr &&
      !runtime->has_sensor_importance()) {
    throw std::invalid_argument(
        "PortalSetLighting: bouncing to the sensors needs their importance");
  }
}

// The exact suns of one state, shadowed by `geometry`'s occluders, named by their portals.
class SunDirectLights : public DirectLights {
 public:
  SunDirectLights(SunGeometry geometry, std::vector<PortalSun> suns,
                  std::span<const Portal> portals)
      : geometry_(std::move(geometry)), suns_(std::move(suns)), portals_(portals) {}
  Rgb irradiance_at(Vec3 p, Vec3 n) const override {
    return sun_irradiance(geometry_, suns_, p, n);
  }
  void for_each_at(Vec3 p, Vec3 n, bool with_luminance,
                   const SeenLightVisit& visit) const override {
    for (const PortalSun& sun : suns_) {
      visit(LightKind::kSun, portals_[sun.portal].name,
            sun_seen_from(geometry_, sun, p, n, with_luminance));
    }
  }

 private:
  SunGeometry geometry_;
  std::vector<PortalSun> suns_;
  std::span<const Portal> portals_;
};

// No light at a point (a scene without suns).
class NoDirectLights : public DirectLights {
 public:
  Rgb irradiance_at(Vec3 /*p*/, Vec3 /*n*/) const override { return {}; }
  void for_each_at(Vec3 /*p*/, Vec3 /*n*/, bool /*with_luminance*/,
                   const SeenLightVisit& /*visit*/) const override {}
};

}  // namespace

void update_portal_lighting(PortalLighting& lighting, std::uint32_t index,
                            const PortalTransferView& portal, int sh_order,
                            const PortalState& state, const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const Environment environment = [&] {
    try {
      return load_environment(state.environment);
    } catch (const InputError& e) {  // e.g. a map file moved since the precompute
      fail_input(state.environment.where, e.what());
    }
  }();
  const std::vector<ExteriorObject> exterior = placed_exterior(scene, state.exterior);
  ShellInputs inputs;
  inputs.environment = &environment;
  inputs.tint = state.tint;
  inputs.frost_deg = state.frost_deg;
  inputs.glazing = state.glazing ? &*state.glazing : nullptr;
  inputs.exterior = exterior;
  // The indirect weights are the SH of the shell's outward half: no light from behind the
  // portal's plane can pass it (its direct transfer is zero), but in a band-limited projection
  // of the whole shell a bright feature there — a sun behind the building, a bright map
  // region — rings into the directions that do pass and lights the room through the indirect
  // transfer (a map of high contrast through a window: floor error against the reference
  // 4.4 % mean, 16 % worst unmasked; see docs/decisions.md).
  inputs.sh_outward_half = true;
  // A sun in front of clear glass is traced exactly (portal_sun.h), not put into the shell;
  // frosted and diffusing glass spread it, in the shell.
  const std::optional<SunDisc>& sun = environment.sun();
  const bool diffusing = state.glazing && state.glazing->diffusing;
  const bool exact_sun = sun && state.frost_deg == 0 && !diffusing && sun->normal_illuminance > 0 &&
                         dot(sun->direction, portal.outward) > 0;
  inputs.sun_disc = !exact_sun;
  const Shell& shell = lighting.shell;
  render_shell(inputs, {portal.centre, portal.outward}, portal.face_size, sh_order, lighting.shell,
               lighting.workspace);
  prepare_shell_cubemap(portal.face_size, shell.cubemap, lighting.cubemap);
  lighting.sun.reset();
  if (exact_sun) {
    const double glass =
        state.glazing
            ? glazing_transmittance(*state.glazing, dot(sun->direction, normalize(portal.outward)))
            : 1.0;
    lighting.sun = make_portal_sun(index, *sun, state.tint * (glass * sun->normal_illuminance),
                                   exterior_tracer(exterior));
  }
  const auto k = static_cast<std::size_t>(sh_count(sh_order));
  lighting.weights.resize(3 * k);
  lighting.active = exact_sun && max_component(state.tint) > 0;
  for (std::size_t b = 0; b < k; ++b) {
    const Rgb c = shell.sh[b];
    lighting.weights[3 * b] = static_cast<float>(c.r);
    lighting.weights[3 * b + 1] = static_cast<float>(c.g);
    lighting.weights[3 * b + 2] = static_cast<float>(c.b);
    lighting.active = lighting.active || c.r != 0 || c.g != 0 || c.b != 0;
  }
  lighting.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

PortalSetLighting::PortalSetLighting(PortalTransferSet transfer, const RuntimeScene* runtime,
                                     const Scene& scene, SunBounce sun_bounce)
    : transfer_(transfer), runtime_(runtime), scene_(&scene), sun_bounce_(sun_bounce) {
  check_sun_bounce(runtime_, sun_bounce_);
  if (transfer_.portals.size() != scene.portals.size() ||
      (!scene.portals.empty() && (!runtime || runtime->receivers() != transfer_.receivers))) {
    throw std::invalid_argument("PortalSetLighting: transfer and scene disagree on portals");
  }
  for (const Portal& p : scene.portals) states_.push_back(portal_state(p, scene.exterior.size()));
  portals_.resize(scene.portals.size());
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (runtime_) bounds_.push_back(runtime_->glass_bounds(static_cast<std::uint32_t>(p)));
    update_portal_lighting(portals_[p], static_cast<std::uint32_t>(p), transfer_.portals[p],
                           transfer_.sh_order, states_[p], scene);
  }
  update_suns();
}

SunGeometry PortalSetLighting::sun_geometry() const {
  if (runtime_ == nullptr) throw std::logic_error("PortalSetLighting: no portals, no sun geometry");
  return {runtime_->occluders(), runtime_->glass(), bounds_};
}

std::unique_ptr<const DirectLights> PortalSetLighting::direct_lights(
    const Occluders& occluders, int /*opening_samples*/) const {
  if (suns_.empty()) return std::make_unique<NoDirectLights>();
  SunGeometry geometry = sun_geometry();
  geometry.occluders = occluders;
  return std::make_unique<SunDirectLights>(std::move(geometry), suns_, scene_->portals);
}

void PortalSetLighting::update_suns() {
  std::vector<SunKey> keys;
  std::vector<PortalSun> suns;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (const std::optional<PortalSun>& s = portals_[p].sun) {
      keys.push_back({s->portal, s->disc.direction, s->illuminance, states_[p].exterior});
      suns.push_back(*s);
    }
  }
  if (keys == sun_keys_) return;
  const auto start = std::chrono::steady_clock::now();
  sun_keys_ = std::move(keys);
  suns_ = std::move(suns);
  sun_bounce_seconds_ = 0;
  if (suns_.empty()) {
    sun_direct_.clear();
    sun_indirect_.clear();
    sun_glossy_.clear();
    sun_seconds_ = 0;
    return;
  }
  const std::size_t n = runtime_->receivers();
  const SunGeometry geometry = sun_geometry();
  // The direct sun at every receiver (at the sensors alone when only they are read) where its
  // shadow rays start.
  const bool sensors_only = sun_bounce_ == SunBounce::kSensors;
  const std::size_t first = sensors_only ? runtime_->vertex_count() : 0;
  sun_direct_.assign(3 * n, 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, n, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const Rgb e = sun_irradiance(geometry, suns_, runtime_->ray_point(r), runtime_->normal(r));
      sun_direct_[3 * r] = static_cast<float>(e.r);
      sun_direct_[3 * r + 1] = static_cast<float>(e.g);
      sun_direct_[3 * r + 2] = static_cast<float>(e.b);
    }
  });
  // Its interreflection: what each vertex reflects is the sun's mean over its hat function
  // (up to 4² points a triangle, sub-triangles no smaller than 5 cm, each point seeing the
  // disc's centre or not: a patch edge crossing a triangle is placed to a quarter of its
  // width or 5 cm), over the triangles the sun may reach, bounced through the stored gather
  // operator; a sun that moved a little starts from the last solution (bounce_solver.h).
  const bool warm = sun_bounce_ == SunBounce::kWarm && sun_indirect_.size() == 3 * n;
  if (!warm) sun_indirect_.assign(3 * n, 0.0f);
  if (runtime_->can_bounce()) {
    std::vector<float> reflected(3 * n);
    runtime_->hat_means(
        [&](Vec3 p, Vec3 normal) { return sun_irradiance(geometry, suns_, p, normal, false); }, 4,
        reflected,
        [&](Vec3 a, Vec3 b, Vec3 c, Vec3 normal) {
          return sun_may_light_triangle(geometry, suns_, a, b, c, normal);
        },
        0.05);
    sun_bounce_seconds_ = sensors_only ? runtime_->bounce_to_sensors(reflected, sun_indirect_)
                                       : runtime_->bounce(reflected, sun_indirect_, warm);
    respond_glossy(geometry, reflected);
  }
  sun_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void PortalSetLighting::set_sun_bounce(SunBounce sun_bounce) {
  if (sun_bounce == sun_bounce_) return;
  check_sun_bounce(runtime_, sun_bounce);
  sun_bounce_ = sun_bounce;
  sun_keys_.clear();
  sun_indirect_.clear();
  update_suns();
}

void PortalSetLighting::set_glossy(const GlossyFirstBounce* glossy) {
  const GlossyFirstBounce* now = glossy != nullptr && !glossy->empty() ? glossy : nullptr;
  if (now == glossy_ && now == nullptr) return;
  glossy_ = now;
  // The suns' light made again with their Γ, solved from nothing as at construction (a warm
  // start stops at a looser tolerance: the same scene would light differently).
  sun_keys_.clear();
  sun_indirect_.clear();
  update_suns();
}

void PortalSetLighting::respond_glossy(const SunGeometry& geometry,
                                       std::span<const float> reflected) {
  sun_glossy_.clear();
  if (glossy_ == nullptr || runtime_ == nullptr) return;
  const std::size_t n = runtime_->receivers();
  sun_glossy_.assign(3 * n, 0.0f);
  std::vector<float> response(3 * n), own(suns_.size() > 1 ? 3 * n : 0);
  for (const PortalSun& sun : suns_) {
    // The sun's own light at the vertices: the suns' together when there is one.
    std::span<const float> direct = reflected;
    if (suns_.size() > 1) {
      runtime_->hat_means(
          [&](Vec3 p, Vec3 normal) {
            return sun_irradiance(geometry, std::span(&sun, 1), p, normal, false);
          },
          4, own,
          [&](Vec3 a, Vec3 b, Vec3 c, Vec3 normal) {
            return sun_may_light_triangle(geometry, std::span(&sun, 1), a, b, c, normal);
          },
          0.05);
      direct = own;
    }
    const Vec3 s = sun.disc.direction;
    const std::vector<float> dx(n, static_cast<float>(-s.x)), dy(n, static_cast<float>(-s.y)),
        dz(n, static_cast<float>(-s.z));
    const MirrorReflection* mirrors = glossy_->mirrors();
    if (mirrors == nullptr) {
      glossy_->respond(dx, dy, dz, direct, response);
    } else {
      // The sun's image in the near-mirror planes (engine/mirror_reflection.h): its normal
      // illuminance where each path meets the mirror, through the glass and past what shades it.
      const std::vector<MirrorPath> paths = mirrors->trace_parallel(s);
      std::vector<float> normal(3 * paths.size());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, paths.size(), 256), [&](const auto& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
          const MirrorPath& path = paths[k];
          const Rgb e =
              sun_irradiance(geometry, std::span(&sun, 1), {path.at[0], path.at[1], path.at[2]},
                             runtime_->normal(path.vertex), false) /
              static_cast<double>(path.cos_in);
          normal[3 * k] = static_cast<float>(e.r);
          normal[3 * k + 1] = static_cast<float>(e.g);
          normal[3 * k + 2] = static_cast<float>(e.b);
        }
      });
      const MirrorLight mirror{paths, normal, 3};
      glossy_->respond(dx, dy, dz, direct, response, &mirror);
    }
    for (std::size_t i = 0; i < 3 * n; ++i) sun_glossy_[i] += response[i];
  }
}

void PortalSetLighting::add_glossy(std::span<float> out) const {
  if (sun_glossy_.size() != out.size()) return;
  for (std::size_t i = 0; i < out.size(); ++i) out[i] += sun_glossy_[i];
}

bool PortalSetLighting::set_state(std::span<const PortalState> states) {
  if (states.size() != portals_.size()) {
    throw std::invalid_argument("PortalSetLighting: one state per portal");
  }
  bool changed = false;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (states[p] == states_[p]) continue;
    states_[p] = states[p];
    update_portal_lighting(portals_[p], static_cast<std::uint32_t>(p), transfer_.portals[p],
                           transfer_.sh_order, states_[p], *scene_);
    changed = true;
  }
  if (changed) update_suns();
  return changed;
}

void PortalSetLighting::add_block(std::size_t b, bool include_direct,
                                  float (&acc)[3][kBlock]) const {
  const std::size_t n = transfer_.receivers;
  const auto kp = static_cast<std::size_t>(sh_count(transfer_.sh_order));
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    const PortalLighting& l = portals_[p];
    if (!l.active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    // The records are summed while the block's indirect transfer, read next, is fetched.
    add_receiver_cubemaps(v.records, v.offsets.subspan(base, count + 1), l.cubemap,
                          std::span(acc[0], count), std::span(acc[1], count),
                          std::span(acc[2], count), block_bytes(v.indirect, b, kp));
    add_weighted_block(v.indirect, b, kp, l.weights.data(), acc);
  }
  if (sun_direct_.empty()) return;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t r = 3 * (base + i);
    for (std::size_t c = 0; c < 3; ++c) {
      acc[c][i] += sun_indirect_[r + c] + (include_direct ? sun_direct_[r + c] : 0.0f);
    }
  }
}

std::size_t PortalSetLighting::transfer_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (!portals_[p].active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    bytes += v.indirect.size_bytes() + v.records.size_bytes() + v.offsets.size_bytes();
  }
  bytes += (sun_direct_.size() + sun_indirect_.size()) * sizeof(float);
  return bytes;
}

}  // namespace relight
