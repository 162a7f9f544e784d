// The sensors' importance by one adjoint solve; see sensor_importance.h.
#include "engine/sensor_importance.h"

#include <chrono>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

namespace relight {

namespace {

using Gather = Eigen::SparseMatrix<float, Eigen::RowMajor>;

// Sensors summed together in sensor_indirect: one task's slice of every lit vertex's row.
constexpr std::size_t kSensorGrain = 64;

}  // namespace

SensorImportance sensor_importance(const GatherOperator& gather, const Receivers& receivers,
                                   const BounceSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const Gather& g = gather.matrix;
  const std::size_t vertices = receivers.vertex_count, sensors = receivers.sensor_count;
  if (g.rows() != static_cast<Eigen::Index>(receivers.size()) ||
      g.cols() != static_cast<Eigen::Index>(vertices) || vertices + sensors != receivers.size() ||
      receivers.albedo.size() != receivers.size()) {
    throw std::invalid_argument("sensor importance: gather operator and receivers disagree");
  }
  const auto nv = static_cast<Eigen::Index>(vertices), ns = static_cast<Eigen::Index>(sensors);
  // The adjoint system: Gᵀ's vertex block for G, the vertices alone as receivers, the
  // sensors' rows of G as the K columns of the direct light.
  GatherOperator adjoint;
  adjoint.matrix = Gather(g.topRows(nv).transpose());
  Receivers vertex_receivers;
  vertex_receivers.vertex_count = vertices;
  vertex_receivers.positions.assign(receivers.positions.begin(), receivers.positions.begin() + nv);
  vertex_receivers.normals.assign(receivers.normals.begin(), receivers.normals.begin() + nv);
  vertex_receivers.albedo.assign(receivers.albedo.begin(), receivers.albedo.begin() + nv);
  const Eigen::MatrixXf sensor_rows = Eigen::MatrixXf(g.bottomRows(ns)).transpose();  // V × S
  const BounceResult solved =
      solve_bounces(adjoint, vertex_receivers, sensor_rows, settings, false);

  SensorImportance out;
  out.vertices = vertices;
  out.sensors = sensors;
  out.bounces = solved.bounces;
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<float>& w = out.weights[c];
    w.resize(vertices * sensors);
    const Eigen::MatrixXf& indirect = solved.indirect[c];
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 256), [&](const auto& range) {
      for (std::size_t v = range.begin(); v != range.end(); ++v) {
        const Rgb& a = receivers.albedo[v];
        const auto rho = static_cast<float>(c == 0 ? a.r : (c == 1 ? a.g : a.b));
        const auto row = static_cast<Eigen::Index>(v);
        for (std::size_t s = 0; s < sensors; ++s) {
          const auto col = static_cast<Eigen::Index>(s);
          w[v * sensors + s] = rho * (sensor_rows(row, col) + indirect(row, col));
        }
      }
    });
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void sensor_indirect(const SensorImportance& importance, std::span<const float> direct,
                     std::span<float> out) {
  const std::size_t vertices = importance.vertices, sensors = importance.sensors;
  if (direct.size() != 3 * (vertices + sensors) || out.size() != 3 * sensors) {
    throw std::invalid_argument("sensor importance: light and sensors disagree");
  }
  std::vector<std::size_t> lit;  // vertices that reflect any light: a sun lights a patch
  for (std::size_t v = 0; v < vertices; ++v) {
    if (direct[3 * v] != 0 || direct[3 * v + 1] != 0 || direct[3 * v + 2] != 0) lit.push_back(v);
  }
  const auto slices = tbb::blocked_range<std::size_t>(0, sensors, kSensorGrain);
  tbb::parallel_for(
      slices,
      [&](const auto& r) {
        const std::size_t first = r.begin(), count = r.end() - r.begin();
        float sum[3][kSensorGrain] = {};
        for (const std::size_t v : lit) {
          for (std::size_t c = 0; c < 3; ++c) {
            const float e = direct[3 * v + c];
            const float* w = importance.weights[c].data() + v * sensors + first;
            for (std::size_t i = 0; i < count; ++i) sum[c][i] += e * w[i];
          }
        }
        for (std::size_t i = 0; i < count; ++i) {
          for (std::size_t c = 0; c < 3; ++c) out[3 * (first + i) + c] = sum[c][i];
        }
      },
      tbb::simple_partitioner{});  // slices of at most kSensorGrain sensors
}

}  // namespace relight
