#include "sources/object/object_lighting.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "sources/nearfield/emitter_direct.h"

namespace relight {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether a sphere comes within `margin` of the segment from a to b.
bool segment_near_sphere(Vec3 a, Vec3 b, const BoundingSphere& s, double margin) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(s.centre - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(a + ab * t - s.centre) <= s.radius + margin;
}

// Whether a sphere comes within `margin` of the ray from a along unit d.
bool ray_near_sphere(Vec3 a, Vec3 d, const BoundingSphere& s, double margin) {
  const double t = std::max(0.0, dot(s.centre - a, d));
  return length(a + d * t - s.centre) <= s.radius + margin;
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
  source_.assign(3 * rows, 0.0f);
  indirect_.assign(3 * rows, 0.0f);
  room_delta_.assign(3 * room.receivers(), 0.0f);
  object_gather_.assign(3 * rows, 0.0f);
  static_light_.assign(3 * (vertices + placed_.vertex_count()), 0.0f);
  room_delta_direct_.assign(3 * room.receivers(), 0.0f);
  object_total_.assign(3 * placed_.vertex_count(), 0.0f);
  object_indirect_.assign(3 * placed_.vertex_count(), 0.0f);
}

bool ObjectLighting::set_state(std::span<const MovablePlacement> placements) {
  if (placements.size() != placements_.size()) {
    throw std::invalid_argument("ObjectLighting: one placement per object expected");
  }
  if (std::equal(placements.begin(), placements.end(), placements_.begin())) return false;
  for (std::size_t k = 0; k < placements.size(); ++k) {
    const bool pending = std::find(moved_.begin(), moved_.end(), k) != moved_.end();
    if (placements[k] != placements_[k] && !pending)
      moved_.push_back(static_cast<std::uint32_t>(k));
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
  const Occluders with = occluders(), without(room.occluders());
  std::optional<SunGeometry> sun_with;
  if (in.sun_geometry)
    sun_with.emplace(SunGeometry{with, in.sun_geometry->glass, in.sun_geometry->portals});
  const bool suns = in.sun_geometry.has_value() && !in.suns.empty();
  // Spheres around each near-field emitter's triangles (its shadow rays end on them).
  std::vector<BoundingSphere> emitter_spheres;
  if (in.emitters != nullptr && !in.emitters->positions.empty()) {
    for (std::size_t e = 0; e < in.emitters->radiance.size(); ++e) {
      std::vector<Vec3> points;
      for (std::size_t t = 0; t < in.emitters->triangles.size(); ++t) {
        if (in.emitters->emitter_of_triangle[t] != e) continue;
        for (const std::uint32_t v : in.emitters->triangles[t]) {
          points.push_back(in.emitters->positions[v]);
        }
      }
      if (!points.empty()) emitter_spheres.push_back(sphere_around(points));
    }
  }
  // How far each luminaire's opening reaches from its centre.
  std::vector<double> reach;
  for (const LuminaireLight& l : in.luminaires) {
    double r = 0;
    for (const Vec3& o : l.opening) r = std::max(r, length(o));
    reach.push_back(r);
  }
  // A sensor's penumbrae are sampled finer (256 points on each luminous opening and emitter
  // triangle, 16 at vertices): its reading is not averaged between vertices.
  const auto direct_at = [&](const Occluders& occluders, const std::optional<SunGeometry>& sun,
                             Vec3 p, Vec3 n, bool sensor) {
    const bool fine = sensor && in.sensor_luminaires.size() == in.luminaires.size();
    Rgb e =
        luminaire_direct_irradiance(occluders, fine ? in.sensor_luminaires : in.luminaires, p, n);
    if (suns) e += sun_irradiance(*sun, in.suns, p, n);
    if (in.emitters != nullptr) {
      e += emitter_direct_irradiance(*in.emitters, &occluders, p, n, sensor ? 256 : 16);
    }
    return e;
  };
  // Whether a shadow ray from x toward a light may pass the sphere s.
  const auto may_shadow = [&](Vec3 x, const BoundingSphere& s) {
    if (s.radius <= 0) return false;
    for (std::size_t j = 0; j < in.luminaires.size(); ++j) {
      if (max_component(in.luminaires[j].rgb) > 0 &&
          segment_near_sphere(x, in.luminaires[j].position, s, reach[j])) {
        return true;
      }
    }
    for (std::size_t j = 0; suns && j < in.suns.size(); ++j) {
      if (ray_near_sphere(x, in.suns[j].disc.direction, s, 1e-3 + 0.01 * s.radius)) return true;
    }
    for (const BoundingSphere& e : emitter_spheres) {
      if (segment_near_sphere(x, e.centre, s, e.radius)) return true;
    }
    return false;
  };
  // What must be traced again: with `all`, wherever any object may shadow; otherwise only where
  // a moved object may, where it was or where it is now (the rest is kept from the last frame).
  const auto redo = [&](Vec3 x) {
    if (all) {
      for (const BoundingSphere& s : placed_.bounds) {
        if (may_shadow(x, s)) return true;
      }
      return false;
    }
    for (std::size_t i = 0; i < moved_.size(); ++i) {
      if (may_shadow(x, lit_->bounds[moved_[i]]) || may_shadow(x, placed_.bounds[moved_[i]])) {
        return true;
      }
    }
    return false;
  };
  // Room receivers: the light the objects' shadows take away, where a shadow ray may pass an
  // object.
  if (all) std::fill(direct_.begin(), direct_.end(), 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, room.receivers(), 256), [&](const auto& rr) {
    for (std::size_t r = rr.begin(); r != rr.end(); ++r) {
      const Vec3 x = room.ray_point(r), n = room.normal(r);
      if (!redo(x)) continue;
      // A sensor's penumbra is sampled finer: its reading is not averaged between vertices.
      const bool sensor = r >= vertices;
      const Rgb e = direct_at(with, sun_with, x, n, sensor) -
                    direct_at(without, in.sun_geometry, x, n, sensor);
      put(direct_, r < vertices ? r : r + objects, e);
    }
  });
  // Object vertices: their whole direct light.
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, placed_.object_count()), [&](const auto& kr) {
        for (std::size_t k = kr.begin(); k != kr.end(); ++k) {
          const bool moved = all || std::find(moved_.begin(), moved_.end(), k) != moved_.end();
          tbb::parallel_for(tbb::blocked_range<std::size_t>(placed_.first_vertex[k],
                                                            placed_.first_vertex[k + 1], 64),
                            [&](const auto& qr) {
                              for (std::size_t q = qr.begin(); q != qr.end(); ++q) {
                                if (!placed_.visible(k)) {
                                  put(direct_, vertices + q, Rgb{});
                                } else if (moved || redo(placed_.ray_points[q])) {
                                  put(direct_, vertices + q,
                                      direct_at(with, sun_with, placed_.ray_points[q],
                                                placed_.normals[q], false));
                                }
                              }
                            });
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
  // D = ΔE_d + [C; H] · ρE0 + the windows' light the objects gain or hide. Transfer rows:
  // room receiver r is row r, object vertex q row R + q (object_transfer.h); solver rows: room
  // vertices, object vertices, sensors — the first two also the unified columns.
  const auto unified = [&](std::size_t row) {
    return row < vertices ? row : (row < receivers ? row + objects : row - receivers + vertices);
  };
  // ρE0 per column (objects have no light in E0).
  std::fill(static_light_.begin(), static_light_.end(), 0.0f);
  for (std::size_t i = 0; i < 3 * vertices; ++i) static_light_[i] = albedo_[i] * in.room[i];
  std::copy(direct_.begin(), direct_.end(), source_.begin());
  apply_object_rows(static_light_, source_);
  if (in.glass) add_glass_light(in.glass, source_);
  // ΔE = D + [G + C; H] · ρ ΔE over room vertices and object vertices; sensors gathered once:
  // the objects' rows applied once per sweep, the room's G row by row.
  const auto& g = room.gather().matrix;
  const auto prepare = [&](std::span<const float> reflected) {
    std::fill(object_gather_.begin(), object_gather_.end(), 0.0f);
    apply_object_rows(reflected, object_gather_);
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
  timings_.bounces = solve_bounces_rgb(op, source_, indirect_, warm_, bounce);
  warm_ = true;
  for (std::size_t r = 0; r < receivers; ++r) {
    const std::size_t u = unified(r);
    for (std::size_t k = 0; k < 3; ++k) {
      room_delta_[3 * r + k] = source_[3 * u + k] + indirect_[3 * u + k];
      room_delta_direct_[3 * r + k] = direct_[3 * u + k];
    }
  }
  for (std::size_t q = 0; q < objects; ++q) {
    const std::size_t u = vertices + q;
    for (std::size_t k = 0; k < 3; ++k) {
      object_total_[3 * q + k] = source_[3 * u + k] + indirect_[3 * u + k];
      object_indirect_[3 * q + k] = object_total_[3 * q + k] - direct_[3 * u + k];
    }
  }
  timings_.bounce_seconds = seconds_since(start);
}

namespace {

// Σ_e values[e] · light[3 column_e ..] over row i of `rows`, added to sum.
void add_row(const ObjectRows& rows, std::size_t i, std::span<const float> light, float* sum) {
  for (std::size_t e = rows.first[i]; e < rows.first[i + 1]; ++e) {
    const float* l = &light[3 * std::size_t{rows.columns[e]}];
    sum[0] += rows.values[e] * l[0];
    sum[1] += rows.values[e] * l[1];
    sum[2] += rows.values[e] * l[2];
  }
}

}  // namespace

void ObjectLighting::apply_object_rows(std::span<const float> light, std::span<float> out) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count();
  const auto unified = [&](std::size_t row) {
    return row < vertices ? row : (row < receivers ? row + objects : row - receivers + vertices);
  };
  // Every object's cone rows (rows of different objects are the same receivers: one object at
  // a time), then the base rows.
  for (const ObjectRows& cone : transfer_.cones) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cone.rows(), 1024), [&](const auto& rr) {
      for (std::size_t row = rr.begin(); row != rr.end(); ++row) {
        if (cone.first[row] != cone.first[row + 1]) {
          add_row(cone, row, light, &out[3 * unified(row)]);
        }
      }
    });
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, objects, 1024), [&](const auto& qr) {
    for (std::size_t q = qr.begin(); q != qr.end(); ++q) {
      add_row(transfer_.base, q, light, &out[3 * (vertices + q)]);
    }
  });
  // The vertices that take a layer's row from proxies (each object's cones, then the base).
  const ReceiverProxies& proxies = transfer_.proxies;
  const std::size_t layers = transfer_.cones.size() + 1, count = proxies.proxies.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 256), [&](const auto& jr) {
    for (std::size_t j = jr.begin(); j != jr.end(); ++j) {
      const std::size_t c = proxies.proxies[j];
      for (std::size_t l = 0; l < layers; ++l) {
        float* sum = &proxy_values_[3 * (l * count + j)];
        sum[0] = sum[1] = sum[2] = 0;
        if (l + 1 < layers) {
          add_row(transfer_.cones[l], c < vertices ? c : receivers + (c - vertices), light, sum);
        } else if (c >= vertices) {
          add_row(transfer_.base, c - vertices, light, sum);
        }
      }
    }
  });
  spread_from_proxies(proxies, proxy_layers_, proxy_values_,
                      out.subspan(0, 3 * (vertices + objects)));
}

void ObjectLighting::add_glass_light(const GlassLuminance& glass, std::span<float> out) {
  const RuntimeScene& room = *room_;
  const std::size_t vertices = room.vertex_count(), receivers = room.receivers();
  const std::size_t objects = placed_.vertex_count();
  const ReceiverProxies& proxies = transfer_.proxies;
  const std::size_t layers = transfer_.cones.size() + 1, count = proxies.proxies.size();
  // Solver row and proxy (−1: none) of a transfer row.
  const auto unified = [&](std::size_t row) {
    return row < vertices ? row : (row < receivers ? row + objects : row - receivers + vertices);
  };
  const auto proxy = [&](std::size_t row) {
    return row >= vertices && row < receivers ? -1 : proxies.proxy_of[unified(row)];
  };
  std::fill(proxy_values_.begin(), proxy_values_.end(), 0.0f);
  const auto add = [&](const GlassHit& g, std::size_t row, std::size_t layer) {
    const Rgb l = glass(g.portal, g.direction) * (kPi * g.weight);
    const float light[3] = {static_cast<float>(l.r), static_cast<float>(l.g),
                            static_cast<float>(l.b)};
    const std::int32_t j = proxy(row);
    for (std::size_t k = 0; k < 3; ++k) {
      out[3 * unified(row) + k] += light[k];
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
