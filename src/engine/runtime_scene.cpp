#include "engine/runtime_scene.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/frame.h"

namespace relight {

namespace {

std::vector<Vec3> copy(std::span<const Vec3> s) {
  return {s.begin(), s.end()};
}

}  // namespace

RuntimeScene::RuntimeScene(const RuntimeSceneView& view, BounceSettings bounce)
    : vertex_count_(view.vertex_count),
      positions_(copy(view.mesh_positions)),
      triangles_(view.opaque_triangles),
      opaque_ids_(view.opaque_ids),
      occluders_(positions_, view.opaque_triangles, view.opaque_ids),
      glass_(positions_, view.glass_triangles, view.glass_portal),
      bounce_(bounce) {
  const std::size_t n = view.receiver_positions.size();
  if (view.receiver_normals.size() != n || view.vertex_count > n ||
      view.mesh_positions.size() != view.vertex_count ||
      view.vertex_albedo.size() != 3 * view.vertex_count ||
      view.glass_portal.size() != view.glass_triangles.size() ||
      view.opaque_ids.size() != view.opaque_triangles.size()) {
    throw std::invalid_argument("RuntimeScene: receivers, mesh and albedo disagree");
  }
  for (std::size_t t = 0; t < view.opaque_ids.size(); ++t) {
    const std::uint32_t id = view.opaque_ids[t];
    if (id >= opaque_slot_.size()) opaque_slot_.resize(std::size_t{id} + 1, 0);
    opaque_slot_[id] = static_cast<std::uint32_t>(t);
  }
  receivers_.positions = view.receiver_positions;
  receivers_.normals = view.receiver_normals;
  receivers_.vertex_count = view.vertex_count;
  receivers_.sensor_count = n - view.vertex_count;
  receivers_.albedo.assign(n, Rgb{});
  for (std::size_t v = 0; v < view.vertex_count; ++v) {
    receivers_.albedo[v] = {view.vertex_albedo[3 * v], view.vertex_albedo[3 * v + 1],
                            view.vertex_albedo[3 * v + 2]};
  }
  // Per portal the box around its glass vertices, then the farthest vertex from its centre.
  std::vector<std::pair<Vec3, Vec3>> boxes;
  for (std::size_t t = 0; t < view.glass_triangles.size(); ++t) {
    const std::uint32_t p = view.glass_portal[t];
    if (p >= boxes.size())
      boxes.resize(p + 1, {Vec3{1e300, 1e300, 1e300}, Vec3{-1e300, -1e300, -1e300}});
    for (const std::uint32_t v : view.glass_triangles[t]) {
      boxes[p].first = min(boxes[p].first, positions_[v]);
      boxes[p].second = max(boxes[p].second, positions_[v]);
    }
  }
  glass_bounds_.resize(boxes.size());
  std::vector<double> largest(boxes.size(), 0.0);  // the area of the triangle giving the normal
  for (std::size_t p = 0; p < boxes.size(); ++p) {
    if (boxes[p].first.x <= boxes[p].second.x)
      glass_bounds_[p].sphere.centre = (boxes[p].first + boxes[p].second) * 0.5;
  }
  for (std::size_t t = 0; t < view.glass_triangles.size(); ++t) {
    GlassBounds& b = glass_bounds_[view.glass_portal[t]];
    const auto& tri = view.glass_triangles[t];
    const Vec3 face =
        cross(positions_[tri[1]] - positions_[tri[0]], positions_[tri[2]] - positions_[tri[0]]);
    if (length(face) > largest[view.glass_portal[t]]) {
      largest[view.glass_portal[t]] = length(face);
      b.normal = normalize(face);
    }
    for (const std::uint32_t v : tri)
      b.sphere.radius = std::max(b.sphere.radius, length(positions_[v] - b.sphere.centre));
  }
  for (GlassBounds& b : glass_bounds_) {
    const Frame frame = frame_from_normal(b.normal);
    b.u = frame.t;
    b.v = frame.b;
    b.u_min = b.v_min = 1e300;
    b.u_max = b.v_max = -1e300;
  }
  for (std::size_t t = 0; t < view.glass_triangles.size(); ++t) {
    GlassBounds& b = glass_bounds_[view.glass_portal[t]];
    for (const std::uint32_t v : view.glass_triangles[t]) {
      const Vec3 d = positions_[v] - b.sphere.centre;
      b.u_min = std::min(b.u_min, dot(d, b.u));
      b.u_max = std::max(b.u_max, dot(d, b.u));
      b.v_min = std::min(b.v_min, dot(d, b.v));
      b.v_max = std::max(b.v_max, dot(d, b.v));
      b.depth = std::max(b.depth, std::abs(dot(d, b.normal)));
    }
  }
  for (GlassBounds& b : glass_bounds_) {
    if (b.u_min > b.u_max) b.u_min = b.u_max = b.v_min = b.v_max = 0;  // no glass
  }
  PreparedMesh mesh;
  mesh.positions = positions_;
  mesh.triangles = triangles_;
  ray_points_ = receiver_ray_points(receivers_, mesh);
  if (!view.gather_rows.empty()) {
    // The stored operator, copied once into the solver's matrix.
    const Eigen::Map<const Eigen::SparseMatrix<float, Eigen::RowMajor>> map(
        static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(view.vertex_count),
        static_cast<Eigen::Index>(view.gather_values.size()),
        reinterpret_cast<const int*>(view.gather_rows.data()),
        reinterpret_cast<const int*>(view.gather_columns.data()), view.gather_values.data());
    gather_.emplace();
    gather_->matrix = map;
  }
  // The triangles around each vertex, and ∫ φ_v dA = Σ A_t / 3 over them.
  std::vector<std::size_t> count(vertex_count_ + 1, 0);
  for (const Triangle& t : triangles_) {
    for (const std::uint32_t v : t) ++count[v + 1];
  }
  corner_first_.assign(vertex_count_ + 1, 0);
  for (std::size_t v = 0; v < vertex_count_; ++v)
    corner_first_[v + 1] = corner_first_[v] + count[v + 1];
  corners_.resize(corner_first_.back());
  std::vector<std::size_t> next(corner_first_.begin(), corner_first_.end() - 1);
  hat_area_.assign(vertex_count_, 0.0);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Triangle& tri = triangles_[t];
    const double area = 0.5 * length(cross(positions_[tri[1]] - positions_[tri[0]],
                                           positions_[tri[2]] - positions_[tri[0]]));
    for (std::uint32_t k = 0; k < 3; ++k) {
      corners_[next[tri[k]]++] = static_cast<std::uint32_t>(3 * t + k);
      hat_area_[tri[k]] += area / 3;
    }
  }
}

void RuntimeScene::hat_means(const IrradianceField& irradiance, int subdivision,
                             std::span<float> out, const TriangleFilter& may_light,
                             double min_edge) const {
  const std::size_t n = receivers();
  if (out.size() != 3 * n || subdivision < 0) {
    throw std::invalid_argument("RuntimeScene::hat_means: bad output size or subdivision");
  }
  // Per triangle corner: ∫ E φ_corner over the triangle.
  std::vector<Rgb> corner(3 * triangles_.size());

  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, triangles_.size(), 64), [&](const auto& range) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
          const Triangle& tri = triangles_[t];
          const Vec3 a = positions_[tri[0]], b = positions_[tri[1]], c = positions_[tri[2]];
          const Vec3 face = cross(b - a, c - a);
          const double area = 0.5 * length(face);
          if (!(area > 0)) continue;
          const Vec3 normal = face / (2 * area);
          if (may_light && !may_light(a, b, c, normal)) continue;
          int s = subdivision;
          if (s > 1 && min_edge > 0) {
            const double longest = std::max({length(b - a), length(c - b), length(a - c)});
            s = std::clamp(static_cast<int>(std::ceil(longest / min_edge)), 1, s);
          }
          const double inv = s > 0 ? 1.0 / s : 0.0;
          const double weight = s > 0 ? area / (s * s) : 0.0;
          std::array<Rgb, 3> sum{};
          const auto add = [&](double u, double v) {  // barycentrics toward b and c
            const Rgb e = irradiance(a + (b - a) * u + (c - a) * v, normal) * weight;
            sum[0] += e * (1 - u - v);
            sum[1] += e * u;
            sum[2] += e * v;
          };
          if (s == 0) {  // per corner its φ-weighted centroid, barycentric (½, ¼, ¼)
            const double w = area / 3;
            sum[0] += irradiance(a * 0.5 + (b + c) * 0.25, normal) * w;
            sum[1] += irradiance(b * 0.5 + (a + c) * 0.25, normal) * w;
            sum[2] += irradiance(c * 0.5 + (a + b) * 0.25, normal) * w;
          }
          for (int i = 0; i < s; ++i) {
            for (int j = 0; i + j < s; ++j) {
              add((i + 1.0 / 3) * inv, (j + 1.0 / 3) * inv);  // the sub-triangle pointing up
              if (i + j + 2 <= s) add((i + 2.0 / 3) * inv, (j + 2.0 / 3) * inv);  // and down
            }
          }
          for (int k = 0; k < 3; ++k)
            corner[3 * t + static_cast<std::size_t>(k)] = sum[static_cast<std::size_t>(k)];
        }
      });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      Rgb e;
      if (r >= vertex_count_) {
        // Sensors reflect nothing: the bounce reads only vertex rows.
      } else if (hat_area_[r] > 0) {
        for (std::size_t i = corner_first_[r]; i < corner_first_[r + 1]; ++i)
          e += corner[corners_[i]];
        e = e / hat_area_[r];
      } else {
        e = irradiance(ray_points_[r], receivers_.normals[r]);
      }
      out[3 * r] = static_cast<float>(e.r);
      out[3 * r + 1] = static_cast<float>(e.g);
      out[3 * r + 2] = static_cast<float>(e.b);
    }
  });
}

double RuntimeScene::bounce(std::span<const float> direct, std::span<float> indirect,
                            bool warm) const {
  if (!gather_) throw std::invalid_argument("RuntimeScene::bounce: no gather operator stored");
  const auto start = std::chrono::steady_clock::now();
  solve_bounces_rgb(*gather_, receivers_, direct, indirect, warm, bounce_);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void RuntimeScene::solve_sensor_importance(std::shared_ptr<const SensorImportance> solved) {
  if (!gather_) throw std::invalid_argument("RuntimeScene: no gather operator stored");
  if (importance_) return;
  if (solved) {
    if (solved->vertices != vertex_count_ || solved->sensors != receivers() - vertex_count_) {
      throw std::invalid_argument("RuntimeScene: the importance given is another scene's");
    }
    importance_ = std::move(solved);
    return;
  }
  importance_ = std::make_shared<const SensorImportance>(
      relight::sensor_importance(*gather_, receivers_, bounce_));
}

double RuntimeScene::bounce_to_sensors(std::span<const float> direct,
                                       std::span<float> indirect) const {
  if (!importance_) throw std::logic_error("RuntimeScene: the sensors' importance is not solved");
  if (indirect.size() != 3 * receivers()) {
    throw std::invalid_argument("RuntimeScene::bounce_to_sensors: one RGB per receiver");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::size_t first = 3 * vertex_count_;
  std::fill(indirect.begin(), indirect.begin() + static_cast<std::ptrdiff_t>(first), 0.0f);
  sensor_indirect(*importance_, direct, indirect.subspan(first));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace relight
