#include "sources/nearfield/emitter_lighting.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/sh.h"
#include "sources/nearfield/emitter_direct.h"

namespace relight {

namespace {

std::vector<Vec3> copy_positions(std::span<const Vec3> s) {
  return {s.begin(), s.end()};
}

}  // namespace

EmitterLighting::EmitterLighting(const NearfieldTransferView& transfer, const Scene& scene,
                                 EmitterLightingSettings settings)
    : transfer_(&transfer),
      scene_(&scene),
      settings_(settings),
      nearfield_(transfer.receiver_positions, transfer.sh_order),
      occluders_(copy_positions(transfer.mesh_positions), transfer.opaque_triangles,
                 sequential_ids(transfer.opaque_triangles.size())) {
  if (transfer.sh_order < 1 || scene.emitters.empty()) {
    throw std::invalid_argument("EmitterLighting: the scene has no emitters");
  }
  const std::size_t n = transfer.receiver_positions.size();
  const auto k = static_cast<std::size_t>(sh_count(transfer.sh_order));
  if (transfer.transfer.size() != n * k || transfer.receiver_normals.size() != n ||
      transfer.vertex_albedo.size() != 3 * transfer.vertex_count) {
    throw std::invalid_argument("EmitterLighting: transfer and receivers disagree");
  }
  if (!transfer.gather_rows.empty()) {
    // The stored operator, copied once into the solver's matrix.
    const Eigen::Map<const Eigen::SparseMatrix<float, Eigen::RowMajor>> map(
        static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(transfer.vertex_count),
        static_cast<Eigen::Index>(transfer.gather_values.size()),
        reinterpret_cast<const int*>(transfer.gather_rows.data()),
        reinterpret_cast<const int*>(transfer.gather_columns.data()),
        transfer.gather_values.data());
    gather_.emplace();
    gather_->matrix = map;
    receivers_.positions = transfer.receiver_positions;
    receivers_.vertex_count = transfer.vertex_count;
    receivers_.sensor_count = n - transfer.vertex_count;
    receivers_.albedo.assign(n, Rgb{});
    for (std::size_t v = 0; v < transfer.vertex_count; ++v) {
      receivers_.albedo[v] = {transfer.vertex_albedo[3 * v], transfer.vertex_albedo[3 * v + 1],
                              transfer.vertex_albedo[3 * v + 2]};
    }
    // Shadow rays from the vertices start where the precompute's did (engine/receivers.h).
    receivers_.normals = transfer.receiver_normals;
    PreparedMesh mesh;
    mesh.positions = copy_positions(transfer.mesh_positions);
    mesh.triangles = transfer.opaque_triangles;
    ray_points_ = receiver_ray_points(receivers_, mesh);
    // The quadrature of each vertex's hat function φ_v: per adjacent triangle t one point at
    // barycentric (½, ¼, ¼) from v (the φ_v-weighted centroid of t), weight A_t.
    std::vector<std::vector<std::size_t>> around(transfer.vertex_count);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (const std::uint32_t v : mesh.triangles[t]) around[v].push_back(t);
    }
    hat_first_.push_back(0);
    for (std::size_t v = 0; v < transfer.vertex_count; ++v) {
      for (const std::size_t t : around[v]) {
        const Triangle& tri = mesh.triangles[t];
        const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                   c = mesh.positions[tri[2]];
        const Vec3 face = cross(b - a, c - a);
        const double area = 0.5 * length(face);
        if (!(area > 0)) continue;
        const Vec3 p = (a + b + c + mesh.positions[v]) * 0.25;
        hat_points_.push_back({p, face / (2 * area), area});
      }
      hat_first_.push_back(hat_points_.size());
    }
    bounce_.tolerance = scene.precompute.tolerance;
    bounce_.max_bounces = scene.precompute.max_bounces;
  }
  if (ray_points_.empty()) ray_points_ = transfer.receiver_positions;
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

void EmitterLighting::update() {
  if (current_) return;
  relight();
  current_ = true;
}

void EmitterLighting::relight() {
  NearfieldSettings s;
  s.method = NearfieldMethod::kAdaptive;
  s.epsilon = settings_.epsilon;
  s.max_samples = settings_.max_samples;
  s.face_size = settings_.face_size;
  sampling_ = nearfield_.light(placed_, s);
  const std::size_t n = transfer_->receiver_positions.size();
  const auto k = static_cast<std::size_t>(sh_count(transfer_->sh_order));
  // The direct light: Sun 2005's reconstruction at vertices, the exact integral at sensors.
  std::vector<float> direct(3 * n);
  nearfield_irradiance(transfer_->transfer, sampling_.sh, k, direct);
  const std::size_t first = transfer_->vertex_count;
  const auto exact = [&](std::size_t r, int samples) {
    return emitter_direct_irradiance(placed_, &occluders_, ray_points_[r],
                                     transfer_->receiver_normals[r], samples);
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, n), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const Rgb e = exact(r, settings_.visibility_samples);
      direct[3 * r] = static_cast<float>(e.r);
      direct[3 * r + 1] = static_cast<float>(e.g);
      direct[3 * r + 2] = static_cast<float>(e.b);
    }
  });
  indirect_.assign(3 * n, 0.0f);
  bounce_seconds_ = 0;
  if (gather_) {
    // What bounces is the exact direct light at the vertices too (one column per colour
    // channel; channel c of the result is column c bounced with albedo channel c): the SH
    // reconstruction at l < 4 of an emitter half a metre away misplaces its light enough to
    // make the ceiling above a downward panel 12 % too bright (tests/cli/emitter_probe_test.cpp).
    // A vertex's value is the mean of the exact light over its hat function, ∫Eφ_v / ∫φ_v, so
    // that the light interpolated between vertices carries the flux the surfaces receive
    // (the value at the vertex alone underestimates a peaked pool of light: the same ceiling
    // 2.5 % too dark at 0.25 m edges).
    Eigen::MatrixXf columns(static_cast<Eigen::Index>(n), 3);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
      for (std::size_t r = range.begin(); r != range.end(); ++r) {
        Rgb e;
        if (r >= first) {
          e = Rgb{direct[3 * r], direct[3 * r + 1], direct[3 * r + 2]};
        } else if (hat_first_[r] == hat_first_[r + 1]) {
          e = exact(r, settings_.bounce_visibility_samples);
        } else {
          double weight = 0;
          for (std::size_t i = hat_first_[r]; i < hat_first_[r + 1]; ++i) {
            const HatPoint& h = hat_points_[i];
            e += emitter_direct_irradiance(placed_, &occluders_, h.position, h.normal,
                                           settings_.bounce_visibility_samples) *
                 h.weight;
            weight += h.weight;
          }
          e = e / weight;
        }
        const auto row = static_cast<Eigen::Index>(r);
        columns(row, 0) = static_cast<float>(e.r);
        columns(row, 1) = static_cast<float>(e.g);
        columns(row, 2) = static_cast<float>(e.b);
      }
    });
    const BounceResult bounced = solve_bounces(*gather_, receivers_, columns, bounce_, false);
    bounce_seconds_ = bounced.seconds;
    for (std::size_t r = 0; r < n; ++r) {
      for (int c = 0; c < 3; ++c) {
        indirect_[3 * r + static_cast<std::size_t>(c)] =
            bounced.indirect[static_cast<std::size_t>(c)](static_cast<Eigen::Index>(r), c);
      }
    }
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
