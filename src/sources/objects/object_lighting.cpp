#include "sources/objects/object_lighting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "material/material_reflectance.h"
#include "sources/emitters/emitter_direct.h"

namespace relight {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void put(std::vector<float>& v, std::size_t row, Rgb e) {
  v[3 * row] = static_cast<float>(e.r);
  v[3 * row + 1] = static_cast<float>(e.g);
  v[3 * row + 2] = static_cast<float>(e.b);
}

}  // namespace

ObjectLighting::ObjectLighting(const RuntimeScene& room, std::vector<ObjectMesh> meshes,
                               ObjectTransferSettings settings)
    : room_(&room),
      settings_(settings),
      meshes_(std::move(meshes)),
      placements_(meshes_.size()),
      placed_(place_objects(meshes_, placements_)) {
  if (!room.can_bounce()) {
    throw std::invalid_argument("ObjectLighting: the precompute kept no gather operator");
  }
  const std::size_t vertices = room.vertex_count();
  const std::vector<Rgb>& albedo = room.receiver_set().albedo;
  for (std::size_t v = 0; v < vertices; ++v) {
    albedo_.insert(albedo_.end(), {static_cast<float>(albedo[v].r), static_cast<float>(albedo[v].g),
                                   static_cast<float>(albedo[v].b)});
  }
  albedo_.insert(albedo_.end(), placed_.albedo.begin(), placed_.albedo.end());
  const std::size_t rows = room.receivers() + placed_.vertex_count();
  direct_.assign(3 * rows, 0.0f);
  other_direct_.assign(3 * rows, 0.0f);
  source_.assign(3 * rows, 0.0f);
  indirect_.assign(3 * rows, 0.0f);
  room_delta_.assign(3 * room.receivers(), 0.0f);
  object_gather_.assign(3 * rows, 0.0f);
  static_light_.assign(3 * (vertices + placed_.vertex_count()), 0.0f);
  room_delta_direct_.assign(3 * room.receivers(), 0.0f);
  object_total_.assign(3 * placed_.vertex_count(), 0.0f);
  object_indirect_.assign(3 * placed_.vertex_count(), 0.0f);
}

void ObjectLighting::set_albedo(std::span<const float> room_albedo,
                                std::span<const Material> materials) {
  if (room_albedo.size() != 3 * room_->vertex_count()) {
    throw std::invalid_argument("ObjectLighting: one albedo per room vertex expected");
  }
  std::copy(room_albedo.begin(), room_albedo.end(), albedo_.begin());
  for (ObjectMesh& mesh : meshes_) {
    for (std::size_t v = 0; v < mesh.vertex_material.size(); ++v) {
      const Rgb a = bounce_albedo(materials[mesh.vertex_material[v]],  // validated on read
                                  vertex_texture_at(std::span<const float>(mesh.texture), v));
      mesh.albedo[3 * v] = static_cast<float>(a.r);
      mesh.albedo[3 * v + 1] = static_cast<float>(a.g);
      mesh.albedo[3 * v + 2] = static_cast<float>(a.b);
    }
  }
  // The placed objects' albedo is the meshes' back to back (place_objects).
  placed_.albedo.clear();
  for (const ObjectMesh& mesh : meshes_) {
    placed_.albedo.insert(placed_.albedo.end(), mesh.albedo.begin(), mesh.albedo.end());
  }
  std::copy(placed_.albedo.begin(), placed_.albedo.end(),
            albedo_.begin() + static_cast<std::ptrdiff_t>(room_albedo.size()));
  set_materials(materials);
}

bool ObjectLighting::set_state(std::span<const MovablePlacement> placements) {
  if (placements.size() != placements_.size()) {
    throw std::invalid_argument("ObjectLighting: one placement per object expected");
  }
  if (std::equal(placements.begin(), placements.end(), placements_.begin())) return false;
  for (std::size_t k = 0; k < placements.size(); ++k) {
    const bool pending = std::find(moved_.begin(), moved_.end(), k) != moved_.end();
    if (placements[k] != placements_[k] && !pending) {
      moved_.push_back(static_cast<std::uint32_t>(k));
    }
  }
  placements_.assign(placements.begin(), placements.end());
  if (!lit_) lit_ = std::move(placed_);  // where the objects were when last lit
  placed_ = place_objects(meshes_, placements_);
  warned_.resize(meshes_.size(), false);
  for (const std::uint32_t k : moved_) {
    if (!warned_[k] && passes_through(placed_, k, room_->occluders())) {
      warned_[k] = true;
      warnings_.push_back(meshes_[k].name);
    }
  }
  return true;
}

void ObjectLighting::trace_direct(const ObjectLightInputs& in, bool all) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), objects = placed_.vertex_count();
  const std::size_t rows = room.receivers() + objects;
  const Occluders with = occluders(), without(room.occluders());
  // Every solver row's point and normal (room vertices, object vertices, sensors).
  const auto point = [&](std::size_t u) {
    return u < vertices ? room.ray_point(u)
                        : (u < vertices + objects ? placed_.ray_points[u - vertices]
                                                  : room.ray_point(u - objects));
  };
  const auto normal = [&](std::size_t u) {
    return u < vertices ? room.normal(u)
                        : (u < vertices + objects ? placed_.normals[u - vertices]
                                                  : room.normal(u - objects));
  };
  const auto is_object = [&](std::size_t u) { return u >= vertices && u < vertices + objects; };
  // Whether row u must be traced again for a light that a shadow ray reaches through `near`
  // (near(x, s): a ray from x toward the light may pass sphere s): with `every`, wherever any
  // object may shadow; else only where a moved object may, where it was or is now, and at
  // the moved objects' own vertices.
  const auto redo = [&](std::size_t u, bool every, const auto& near) {
    const Vec3 x = point(u);
    if (every) {
      for (const BoundingSphere& s : placed_.bounds) {
        if (near(x, s)) return true;
      }
      return is_object(u);
    }
    for (const std::uint32_t k : moved_) {
      if (is_object(u) && placed_.object_of_vertex(u - vertices) == k) return true;
      if (near(x, lit_->bounds[k]) || near(x, placed_.bounds[k])) return true;
    }
    return false;
  };

  retraced_.assign(rows, 0);
  // Luminaires: per luminaire and row, what the objects change in its geometry factor (at
  // room receivers with − without the objects; at object vertices the whole factor), kept
  // until the luminaire's position or opening changes or an object moves within reach. A
  // dimmer, colour or aim changes only the evaluation below, not a ray.
  const bool fine = in.sensor_luminaires.size() == in.luminaires.size();
  if (luminaire_shadows_.size() != in.luminaires.size()) {
    luminaire_shadows_.assign(in.luminaires.size(), {});
  }
  for (std::size_t j = 0; j < in.luminaires.size(); ++j) {
    const LuminaireLight& l = in.luminaires[j];
    const std::vector<Vec3>& sensor_opening = fine ? in.sensor_luminaires[j].opening : l.opening;
    LuminaireShadows& cache = luminaire_shadows_[j];
    const bool stale = cache.factor.size() != rows || cache.position != l.position ||
                       cache.opening != l.opening || cache.sensor_opening != sensor_opening;
    if (stale) {
      cache = {l.position,
               l.opening,
               sensor_opening,
               std::vector<float>(rows, 0.0f),
               std::vector<float>(rows, std::numeric_limits<float>::quiet_NaN()),
               std::vector<OpeningMask>(rows)};
    }
    double reach = 0;
    for (const Vec3& o : l.opening) reach = std::max(reach, length(o));
    const auto near = [&](Vec3 x, const BoundingSphere& s) {
      return s.radius > 0 && segment_near_sphere(x, l.position, s, reach);
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 256), [&](const auto& range) {
      std::uint64_t rays = 0;
      for (std::size_t u = range.begin(); u != range.end(); ++u) {
        if (!redo(u, stale, near)) continue;
        retraced_[u] = 1;
        const Vec3 x = point(u), n = normal(u);
        const std::vector<Vec3>& opening = u >= vertices + objects ? sensor_opening : l.opening;
        double f = 0;
        if (is_object(u)) {
          if (placed_.visible(placed_.object_of_vertex(u - vertices))) {
            f = direct_factor(with, x, n, l.position, opening, rays).factor;
          }
        } else if (opening.size() > kMaxOpeningMask) {
          if (std::isnan(cache.room_factor[u])) {  // the empty room's: traced once
            cache.room_factor[u] =
                static_cast<float>(direct_factor(without, x, n, l.position, opening, rays).factor);
          }
          f = direct_factor(with, x, n, l.position, opening, rays).factor - cache.room_factor[u];
        } else if (const double g = direct_geometry(x, n, l.position); g > 0) {
          // The points the empty room leaves visible, traced once; then only those against
          // the objects.
          if (std::isnan(cache.room_factor[u])) {
            cache.room_visible[u] = visible_opening_points(
                without, x, n, l.position, opening, all_opening_points(opening.size()), rays);
            cache.room_factor[u] = 0;
          }
          const OpeningMask seen = visible_opening_points(placed_.tracer, x, n, l.position, opening,
                                                          cache.room_visible[u], rays);
          f = (opening_point_count(seen) - opening_point_count(cache.room_visible[u])) * g /
              static_cast<double>(opening.size());
        }
        cache.factor[u] = static_cast<float>(f);
      }
    });
  }

  // Suns and near-field emitters: traced again where any object may shadow them whenever the
  // light changed, else where a moved object may.
  std::optional<SunGeometry> sun_with;
  if (in.sun_geometry)
    sun_with.emplace(SunGeometry{with, in.sun_geometry->glass, in.sun_geometry->portals});
  const bool suns = in.sun_geometry.has_value() && !in.suns.empty();
  const bool emitters = in.emitters != nullptr && !in.emitters->positions.empty();
  // Spheres around each near-field emitter's triangles (its shadow rays end on them).
  std::vector<BoundingSphere> emitter_spheres;
  for (std::size_t e = 0; emitters && e < in.emitters->radiance.size(); ++e) {
    std::vector<Vec3> points;
    for (std::size_t t = 0; t < in.emitters->triangles.size(); ++t) {
      if (in.emitters->emitter_of_triangle[t] != e) continue;
      for (const std::uint32_t v : in.emitters->triangles[t]) {
        points.push_back(in.emitters->positions[v]);
      }
    }
    if (!points.empty()) emitter_spheres.push_back(sphere_around(points));
  }
  // A sensor's penumbrae are sampled finer (256 points on each emitter triangle, 16 at
  // vertices): its reading is not averaged between vertices.
  const auto other_at = [&](const Occluders& occluders, const std::optional<SunGeometry>& sun,
                            Vec3 p, Vec3 n, bool sensor) {
    Rgb e;
    if (suns) e += sun_irradiance(*sun, in.suns, p, n);
    if (emitters) e += emitter_direct_irradiance(*in.emitters, &occluders, p, n, sensor ? 256 : 16);
    return e;
  };
  const auto near_other = [&](Vec3 x, const BoundingSphere& s) {
    if (s.radius <= 0) return false;
    for (std::size_t j = 0; suns && j < in.suns.size(); ++j) {
      if (ray_near_sphere(x, in.suns[j].disc.direction, s, 1e-3 + 0.01 * s.radius)) return true;
    }
    for (const BoundingSphere& e : emitter_spheres) {
      if (segment_near_sphere(x, e.centre, s, e.radius)) return true;
    }
    return false;
  };
  if (all || !(suns || emitters)) std::fill(other_direct_.begin(), other_direct_.end(), 0.0f);
  if (suns || emitters) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 256), [&](const auto& range) {
      for (std::size_t u = range.begin(); u != range.end(); ++u) {
        if (!redo(u, all, near_other)) continue;
        retraced_[u] = 1;
        const Vec3 x = point(u), n = normal(u);
        const bool sensor = u >= vertices + objects;
        Rgb e;
        if (is_object(u)) {
          if (placed_.visible(placed_.object_of_vertex(u - vertices))) {
            e = other_at(with, sun_with, x, n, false);
          }
        } else {
          e = other_at(with, sun_with, x, n, sensor) -
              other_at(without, in.sun_geometry, x, n, sensor);
        }
        put(other_direct_, u, e);
      }
    });
  }

  // ΔE_d: the luminaires' factors evaluated for their current output and aim, and the rest;
  // when the light did not change, only at the rows traced again.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 1024), [&](const auto& range) {
    for (std::size_t u = range.begin(); u != range.end(); ++u) {
      if (!all && retraced_[u] == 0) continue;
      Rgb e{other_direct_[3 * u], other_direct_[3 * u + 1], other_direct_[3 * u + 2]};
      for (std::size_t j = 0; j < in.luminaires.size(); ++j) {
        const LuminaireLight& l = in.luminaires[j];
        const float f = luminaire_shadows_[j].factor[u];
        if (f == 0 || max_component(l.rgb) <= 0) continue;
        const Vec3 d = point(u) - l.position;
        const double dist = length(d);
        if (dist <= 0) continue;
        e += luminaire_irradiance(l, d / dist, f);
      }
      put(direct_, u, e);
    }
  });
}

void ObjectLighting::update(const ObjectLightInputs& in, bool light_changed) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count();
  if (in.room.size() != 3 * receivers) {
    throw std::invalid_argument("ObjectLighting: the room's light has the wrong size");
  }
  auto start = std::chrono::steady_clock::now();
  if (!transfer_valid_) {
    transfer_ = trace_object_transfer(room, placed_, settings_);
    transfer_valid_ = true;
  } else if (!moved_.empty()) {
    retrace_object_transfer(transfer_, room, placed_, *lit_, settings_, moved_);
  } else {  // nothing moved: nothing traced
    transfer_.rays = 0;
    transfer_.retraced_rows = 0;
  }
  timings_.rays = transfer_.rays;
  proxy_values_.resize(3 * (transfer_.cones.size() + 1) * transfer_.proxies.proxies.size());
  base_proxied_.assign(vertices + objects, 0);
  for (std::size_t q = 0; q < objects; ++q) {
    base_proxied_[vertices + q] = transfer_.proxies.proxy_of[vertices + q] < 0 ? 1 : 0;
  }
  proxy_layers_.assign(transfer_.proxied.begin(), transfer_.proxied.end());
  proxy_layers_.emplace_back(base_proxied_);
  timings_.transfer_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  trace_direct(in, light_changed || !direct_valid_);
  direct_valid_ = true;
  moved_.clear();
  lit_.reset();
  timings_.direct_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  // D = ΔE_d + [C; H] · ρE0 + the windows' light the objects gain or hide (rows, columns and
  // solver rows: ObjectIndexing).
  const ObjectIndexing indexing(room, placed_);
  // ρE0 per column (objects have no light in E0).
  std::fill(static_light_.begin(), static_light_.end(), 0.0f);
  for (std::size_t i = 0; i < 3 * vertices; ++i) static_light_[i] = albedo_[i] * in.room[i];
  std::copy(direct_.begin(), direct_.end(), source_.begin());
  // Direct light other terms computed with the objects in place: 3 per room receiver, then 3
  // per object vertex, into their solver rows.
  const auto add_source = [&](std::span<const float> at_room, std::span<const float> at_objects,
                              const char* what) {
    if (at_room.empty() && at_objects.empty()) return false;
    if (at_room.size() != 3 * receivers || at_objects.size() != 3 * objects) {
      throw std::invalid_argument(std::string("ObjectLighting: the ") + what +
                                  " direct light has the wrong size");
    }
    for (std::size_t r = 0; r < receivers; ++r) {
      const std::size_t u = r < vertices ? r : r + objects;
      for (std::size_t k = 0; k < 3; ++k) source_[3 * u + k] += at_room[3 * r + k];
    }
    for (std::size_t q = 0; q < objects; ++q) {
      for (std::size_t k = 0; k < 3; ++k) source_[3 * (vertices + q) + k] += at_objects[3 * q + k];
    }
    return true;
  };
  add_source(in.extra_room, in.extra_objects, "extra");
  const bool traced = add_source(in.traced_room, in.traced_objects, "traced");
  if (!direct_only_) {
    apply_object_rows(static_light_, source_, false);
    if (in.glass) add_glass_light(in.glass, source_);
    if (glossy_) add_glossy_reflection(in, source_);
  }
  // ΔE = D + [G + C; H] · ρ ΔE over room vertices and object vertices; sensors gathered once:
  // the objects' rows applied once per sweep, the room's G row by row.
  const auto& g = room.gather().matrix;
  const auto prepare = [&](std::span<const float> reflected, bool sensors_only) {
    std::fill(object_gather_.begin(), object_gather_.end(), 0.0f);
    apply_object_rows(reflected, object_gather_, sensors_only);
  };
  const RgbGather op{vertices + objects, receivers + objects, albedo_,
                     [&](std::size_t u, std::span<const float> reflected, float(&sum)[3]) {
                       if (u >= vertices && u < vertices + objects) {
                         sum[0] = sum[1] = sum[2] = 0;
                       } else {
                         gather_rgb_row(g,
                                        static_cast<Eigen::Index>(u < vertices ? u : u - objects),
                                        reflected, sum);
                       }
                       for (std::size_t k = 0; k < 3; ++k) sum[k] += object_gather_[3 * u + k];
                     },
                     prepare};
  BounceSettings bounce;
  bounce.tolerance = 1e-4;
  if (direct_only_) {
    std::fill(indirect_.begin(), indirect_.end(), 0.0f);
    timings_.bounces = 0;
  } else {
    timings_.bounces = solve_bounces_rgb(op, source_, indirect_, warm_, bounce);
    warm_ = true;
  }
  for (std::size_t r = 0; r < receivers; ++r) {
    const std::size_t u = indexing.solver_row(r);
    for (std::size_t k = 0; k < 3; ++k) {
      room_delta_[3 * r + k] = source_[3 * u + k] + indirect_[3 * u + k];
      room_delta_direct_[3 * r + k] = direct_[3 * u + k] + (traced ? in.traced_room[3 * r + k] : 0);
    }
  }
  for (std::size_t q = 0; q < objects; ++q) {
    const std::size_t u = vertices + q;
    for (std::size_t k = 0; k < 3; ++k) {
      object_total_[3 * q + k] = source_[3 * u + k] + indirect_[3 * u + k];
      object_indirect_[3 * q + k] = object_total_[3 * q + k] - direct_[3 * u + k] -
                                    (traced ? in.traced_objects[3 * q + k] : 0);
    }
  }
  timings_.bounce_seconds = seconds_since(start);
}

namespace {

// Σ_e values[e] · light[3 column_e ..] over row i of `rows`, added to sum.
void add_row(const ObjectRows& rows, std::size_t i, std::span<const float> light, float* sum) {
  for (std::size_t e = rows.begin[i]; e < rows.end[i]; ++e) {
    const float* l = &light[3 * std::size_t{rows.columns[e]}];
    sum[0] += rows.values[e] * l[0];
    sum[1] += rows.values[e] * l[1];
    sum[2] += rows.values[e] * l[2];
  }
}

}  // namespace

void ObjectLighting::apply_object_rows(std::span<const float> light, std::span<float> out,
                                       bool sensors_only) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const ObjectIndexing indexing(room, placed_);
  // Every object's cone rows (rows of different objects are the same receivers: one object at
  // a time), then the base rows. Sensors take no rows from proxies.
  if (sensors_only) {
    for (const ObjectRows& cone : transfer_.cones) {
      for (std::size_t row = vertices; row < receivers; ++row) {
        add_row(cone, row, light, &out[3 * indexing.solver_row(row)]);
      }
    }
    return;
  }
  for_object_rows([&](const ObjectRows& rows, std::size_t i, std::size_t,
                      float* sum) { add_row(rows, i, light, sum); },
                  out);
}

template <typename RowSum>
void ObjectLighting::for_object_rows(const RowSum& row_sum, std::span<float> out) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count();
  const ObjectIndexing indexing(room, placed_);
  // A proxy's row is one of the rows summed: its sum is kept for the vertices that take it.
  const ReceiverProxies& proxies = transfer_.proxies;
  const std::size_t count = proxies.proxies.size();
  std::fill(proxy_values_.begin(), proxy_values_.end(), 0.0f);
  const auto sum_row = [&](const ObjectRows& rows, std::size_t i, std::size_t row,
                           std::size_t column, std::size_t layer, float* target) {
    float sum[3] = {0, 0, 0};
    row_sum(rows, i, row, sum);
    for (std::size_t k = 0; k < 3; ++k) target[k] += sum[k];
    const std::int32_t j = column < proxies.proxy_of.size() ? proxies.proxy_of[column] : -1;
    if (j >= 0) std::copy_n(sum, 3, &proxy_values_[3 * (layer * count + std::size_t(j))]);
  };
  for (std::size_t l = 0; l < transfer_.cones.size(); ++l) {
    const ObjectRows& cone = transfer_.cones[l];
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cone.rows(), 1024), [&](const auto& rr) {
      for (std::size_t row = rr.begin(); row != rr.end(); ++row) {
        if (!cone.empty(row)) {
          sum_row(cone, row, row, indexing.column(row), l, &out[3 * indexing.solver_row(row)]);
        }
      }
    });
  }
  const std::size_t base_layer = transfer_.cones.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects, 1024), [&](const auto& qr) {
    for (std::size_t q = qr.begin(); q != qr.end(); ++q) {
      if (!transfer_.base.empty(q)) {
        sum_row(transfer_.base, q, receivers + q, vertices + q, base_layer,
                &out[3 * (vertices + q)]);
      }
    }
  });
  // The vertices that take a layer's row from proxies (each object's cones, then the base).
  spread_from_proxies(proxies, proxy_layers_, proxy_values_,
                      out.subspan(0, 3 * (vertices + objects)));
}

void ObjectLighting::add_glossy_reflection(const ObjectLightInputs& in, std::span<float> out) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count(), lights = in.luminaires.size();
  // Per glossy object vertex and luminaire: the irradiance (as ΔE_d has it: the luminaire's
  // factor through room and objects) and the direction toward the luminaire.
  std::vector<Rgb> irradiance(objects * lights);
  std::vector<Vec3> toward(objects * lights);
  bool any = false;
  for (std::size_t q = 0; q < objects; ++q) {
    if (!object_brdf_[q] || !placed_.visible(placed_.object_of_vertex(q))) continue;
    const Vec3 x = placed_.ray_points[q];
    for (std::size_t j = 0; j < lights; ++j) {
      const LuminaireLight& l = in.luminaires[j];
      const float f = luminaire_shadows_[j].factor[vertices + q];
      const Vec3 d = x - l.position;
      const double dist = length(d);
      if (f == 0 || dist <= 0 || max_component(l.rgb) <= 0) continue;
      irradiance[q * lights + j] = luminaire_irradiance(l, d / dist, f);
      toward[q * lights + j] = d / -dist;
      any = true;
    }
  }
  if (!any) return;
  for_object_rows(
      [&](const ObjectRows& rows, std::size_t i, std::size_t row, float* sum) {
        const Vec3 receiver =
            row < receivers ? room.ray_point(row) : placed_.ray_points[row - receivers];
        for (std::size_t e = rows.begin[i]; e < rows.end[i]; ++e) {
          if (rows.columns[e] < vertices) continue;
          const std::size_t q = rows.columns[e] - vertices;
          if (!object_brdf_[q]) continue;
          const Vec3 n = placed_.normals[q];
          Vec3 v = receiver - placed_.positions[q];
          const double d = length(v);
          if (!(d > 0) || dot(n, v) <= 0) continue;
          v = v / d;
          Rgb glossy, diffuse;
          for (std::size_t j = 0; j < lights; ++j) {
            const Rgb& e_j = irradiance[q * lights + j];
            if (max_component(e_j) <= 0) continue;
            glossy +=
                metallic_roughness_brdf(*object_brdf_[q], n, toward[q * lights + j], v) * e_j * kPi;
            diffuse += e_j;
          }
          const float* rho = &albedo_[3 * (vertices + q)];
          const Rgb change{glossy.r - rho[0] * diffuse.r, glossy.g - rho[1] * diffuse.g,
                           glossy.b - rho[2] * diffuse.b};
          sum[0] += rows.values[e] * static_cast<float>(change.r);
          sum[1] += rows.values[e] * static_cast<float>(change.g);
          sum[2] += rows.values[e] * static_cast<float>(change.b);
        }
      },
      out);
}

void ObjectLighting::set_materials(std::span<const Material> materials) {
  object_brdf_.clear();
  for (const ObjectMesh& mesh : meshes_) {
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      std::optional<MetallicRoughness> brdf;
      if (v < mesh.vertex_material.size()) {
        const Material& m = materials[mesh.vertex_material[v]];  // validated on read
        if (m.glossy && !m.portal) {
          brdf = metallic_roughness_of(m);
          brdf->albedo = brdf->albedo * vertex_texture_at(std::span<const float>(mesh.texture), v);
        }
      }
      object_brdf_.push_back(brdf);
    }
  }
  glossy_ = std::any_of(object_brdf_.begin(), object_brdf_.end(),
                        [](const auto& b) { return b.has_value(); });
}

void ObjectLighting::add_glass_light(const GlassLuminance& glass, std::span<float> out) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count();
  const ReceiverProxies& proxies = transfer_.proxies;
  const std::size_t layers = transfer_.cones.size() + 1, count = proxies.proxies.size();
  const ObjectIndexing indexing(room, placed_);
  // The proxy (−1: none) of a transfer row's vertex.
  const auto proxy = [&](std::size_t row) {
    const std::size_t c = indexing.column(row);
    return c == ObjectIndexing::kNone ? -1 : proxies.proxy_of[c];
  };
  std::fill(proxy_values_.begin(), proxy_values_.end(), 0.0f);
  const auto add = [&](const GlassHit& g, std::size_t row, std::size_t layer) {
    const Rgb l = glass(g.portal, g.direction) * (kPi * g.weight);
    const float light[3] = {static_cast<float>(l.r), static_cast<float>(l.g),
                            static_cast<float>(l.b)};
    const std::int32_t j = proxy(row);
    for (std::size_t k = 0; k < 3; ++k) {
      out[3 * indexing.solver_row(row) + k] += light[k];
      if (j >= 0) proxy_values_[3 * (layer * count + static_cast<std::size_t>(j)) + k] += light[k];
    }
  };
  for (std::size_t l = 0; l + 1 < layers; ++l) {
    for (const GlassHit& g : transfer_.cones[l].glass) add(g, g.row, l);
  }
  for (const GlassHit& g : transfer_.base.glass) add(g, receivers + g.row, layers - 1);
  spread_from_proxies(proxies, proxy_layers_, proxy_values_,
                      out.subspan(0, 3 * (vertices + objects)));
}

void ObjectLighting::add_to_room(std::span<float> out, bool include_direct) const {
  if (out.size() != room_delta_.size()) {
    throw std::invalid_argument("ObjectLighting: output size mismatch");
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] += room_delta_[i] - (include_direct ? 0.0f : room_delta_direct_[i]);
  }
}

}  // namespace relight
