// Builds the gather operator of the interreflection engine (see gather_operator.h): rows are traced
// independently in parallel (oneTBB, in fixed chunks of receivers), each row's hits are merged per
// vertex in a per-thread accumulator and appended to its chunk's own buffers, and after each window
// of chunks the window's rows are appended in order to the compressed row-major matrix, whose
// storage is reserved from a traced sample of rows — no lock is taken per ray or per row, the rows
// are never held twice, and the result does not depend on thread scheduling.
#include "engine/gather_operator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "common/progress.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace relight {

namespace {

// Receivers per unit of parallel work: rows of one chunk share their hit buffers.
constexpr std::size_t kChunkRows = 64;

// One thread's row accumulator: a dense weight per mesh vertex, the row that last
// touched each vertex, and the vertices the current row touched. Merging duplicates this
// way costs one sort of the distinct vertices, not of every barycentric weight.
struct RowScratch {
  explicit RowScratch(std::size_t vertices) : weight(vertices, 0.0), row_of(vertices, kNoRow) {}
  static constexpr std::uint64_t kNoRow = std::numeric_limits<std::uint64_t>::max();
  std::vector<double> weight;
  std::vector<std::uint64_t> row_of;
  std::vector<std::uint32_t> touched;
  std::vector<Ray> rays;  // one receiver's, traced together
  std::vector<RayHit> hits;

  void add(std::uint64_t row, std::uint32_t vertex, double w) {
    if (row_of[vertex] != row) {
      row_of[vertex] = row;
      weight[vertex] = 0;
      touched.push_back(vertex);
    }
    weight[vertex] += w;
  }
};

// The rows of one chunk of receivers, merged per vertex.
struct ChunkRows {
  std::vector<std::uint32_t> row_sizes;
  std::vector<std::uint32_t> columns;
  std::vector<float> values;
};

// True when the ray, whose closest opaque hit is `hit`, reaches the front side of that
// triangle before any portal.
bool front_hit(const PreparedMesh& mesh, const TracedScene& traced, const Ray& ray,
               const RayHit& hit) {
  if (!hit.hit()) return false;
  const Triangle& t = mesh.triangles[hit.triangle];
  const Vec3 a = mesh.positions[t[0]];
  const Vec3 face = cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
  if (dot(face, ray.direction) >= 0) return false;  // back sides absorb
  if (traced.portals.triangle_count() > 0 &&
      traced.portals.occluded({ray.origin, ray.direction, 0, hit.t})) {
    return false;  // through a window: the portal transfer's light, not a reflection
  }
  return true;
}

// The cosine-distributed pattern of `rays` local directions (about +z), from the
// scrambled (0,2)-sequence: computed once per ray count, so that no ray pays for its
// square roots and trigonometry; each receiver turns the whole pattern by its own random
// angle about its normal, which decorrelates neighbours as the per-receiver scramble did.
std::vector<Vec3> cosine_pattern(int rays, std::uint64_t seed) {
  Pcg32 rng(seed, ~std::uint64_t{0});
  const std::uint32_t scramble_radius = rng.next_u32(), scramble_angle = rng.next_u32();
  std::vector<Vec3> pattern;
  pattern.reserve(static_cast<std::size_t>(rays));
  for (int i = 0; i < rays; ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    pattern.push_back(
        sample_cosine_hemisphere(unit_interval(van_der_corput(index, scramble_radius)),
                                 unit_interval(sobol2(index, scramble_angle))));
  }
  return pattern;
}

// Traces one receiver's rays and appends its merged row to `out`.
void trace_row(const PreparedMesh& mesh, const TracedScene& traced, Vec3 origin, Vec3 normal,
               std::size_t receiver, const std::vector<Vec3>& pattern, std::uint64_t seed,
               RowScratch& scratch, ChunkRows& out) {
  Pcg32 rng(seed, receiver);
  const double turn = 2 * kPi * rng.next_double();
  const Frame base = frame_from_normal(normal);
  const double c = std::cos(turn), s = std::sin(turn);
  const Frame frame{base.t * c + base.b * s, base.b * c - base.t * s, base.n};
  const double weight = 1.0 / static_cast<double>(pattern.size());
  scratch.touched.clear();
  scratch.rays.clear();
  for (const Vec3& local : pattern) scratch.rays.push_back({origin, frame.to_world(local)});
  scratch.hits.resize(scratch.rays.size());
  traced.opaque.intersect(scratch.rays, scratch.hits);
  for (std::size_t i = 0; i < scratch.rays.size(); ++i) {
    const RayHit& hit = scratch.hits[i];
    if (!front_hit(mesh, traced, scratch.rays[i], hit)) continue;
    const Triangle& t = mesh.triangles[hit.triangle];
    scratch.add(receiver, t[0], (1 - hit.u - hit.v) * weight);
    scratch.add(receiver, t[1], hit.u * weight);
    scratch.add(receiver, t[2], hit.v * weight);
  }
  std::sort(scratch.touched.begin(), scratch.touched.end());
  for (std::uint32_t vertex : scratch.touched) {
    out.columns.push_back(vertex);
    out.values.push_back(static_cast<float>(scratch.weight[vertex]));
  }
  out.row_sizes.push_back(static_cast<std::uint32_t>(scratch.touched.size()));
}

// The receivers' ray origins, offset off their surfaces.
std::vector<Vec3> ray_origins(const Receivers& receivers, const PreparedMesh& mesh) {
  const std::vector<Vec3> points = receiver_ray_points(receivers, mesh);
  std::vector<Vec3> origins(points.size());
  for (std::size_t r = 0; r < points.size(); ++r) {
    origins[r] = offset_from_surface(points[r], receivers.normals[r]);
  }
  return origins;
}

void check_inputs(const Receivers& receivers, const PreparedMesh& mesh, int rays_per_vertex,
                  int rays_per_sensor) {
  if (rays_per_vertex < 1 || rays_per_sensor < 1) {
    throw std::invalid_argument("gather operator: rays per receiver must be at least 1");
  }
  if (receivers.vertex_count != mesh.positions.size() ||
      receivers.normals.size() != receivers.size()) {
    throw std::invalid_argument("gather operator: receivers do not match the prepared mesh");
  }
}

// Mean entries of `count` rows evenly spaced over [first, last), traced as the build traces them.
double mean_row_entries(const PreparedMesh& mesh, const TracedScene& traced,
                        const Receivers& receivers, const std::vector<Vec3>& origins,
                        std::size_t first, std::size_t last, std::size_t count,
                        const std::vector<Vec3>& pattern, std::uint64_t seed) {
  count = std::min(count, last - first);
  if (count == 0) return 0;
  tbb::enumerable_thread_specific<RowScratch> scratches(receivers.vertex_count);
  std::vector<std::size_t> entries(count);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const auto& range) {
    RowScratch& scratch = scratches.local();
    ChunkRows row;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const std::size_t r = first + i * (last - first) / count;
      row.row_sizes.clear();
      row.columns.clear();
      row.values.clear();
      trace_row(mesh, traced, origins[r], receivers.normals[r], r, pattern, seed, scratch, row);
      entries[i] = row.row_sizes.front();
    }
  });
  double sum = 0;
  for (const std::size_t e : entries) sum += static_cast<double>(e);
  return sum / static_cast<double>(count);
}

// Rows sample_gather_entries traces: a sample of vertex rows gives their mean within a few per
// cent (a sensor row, of 16 times the rays, costs as much as 16 vertex rows).
constexpr std::size_t kSampledVertexRows = 512, kSampledSensorRows = 32;

// Chunks of rows traced together between two appends to the matrix: enough to keep every
// thread busy, few enough that their buffers stay small beside the matrix.
std::size_t window_chunks() {
  return 8 * static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
}

}  // namespace

GatherEntries sample_gather_entries(const Receivers& receivers, const PreparedMesh& mesh,
                                    const TracedScene& traced, int rays_per_vertex,
                                    int rays_per_sensor, std::uint64_t seed) {
  check_inputs(receivers, mesh, rays_per_vertex, rays_per_sensor);
  const std::vector<Vec3> origins = ray_origins(receivers, mesh);
  GatherEntries out;
  out.per_vertex_row =
      mean_row_entries(mesh, traced, receivers, origins, 0, receivers.vertex_count,
                       kSampledVertexRows, cosine_pattern(rays_per_vertex, seed), seed);
  out.per_sensor_row =
      mean_row_entries(mesh, traced, receivers, origins, receivers.vertex_count, receivers.size(),
                       kSampledSensorRows, cosine_pattern(rays_per_sensor, seed), seed);
  return out;
}

std::uint64_t gather_build_scratch_bytes(const GatherEntries& entries, std::size_t vertices) {
  const auto threads =
      static_cast<std::uint64_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  const double row = std::max(entries.per_vertex_row, entries.per_sensor_row) *
                     static_cast<double>(sizeof(std::uint32_t) + sizeof(float));
  return static_cast<std::uint64_t>(static_cast<double>(window_chunks() * kChunkRows) * row) +
         threads * vertices * (sizeof(double) + sizeof(std::uint64_t));
}

GatherOperator build_gather_operator(const Receivers& receivers, const PreparedMesh& mesh,
                                     const TracedScene& traced, int rays_per_vertex,
                                     int rays_per_sensor, std::uint64_t seed, bool progress,
                                     const RankShares* ranks, const GatherEntries* sampled) {
  check_inputs(receivers, mesh, rays_per_vertex, rays_per_sensor);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t rows = receivers.size();
  const RankShares own = ranks != nullptr ? *ranks : single_process_shares(rows, kChunkRows);
  if (own.receivers != rows || own.block != kChunkRows) {
    throw std::invalid_argument("gather operator: the ranks' blocks are not its chunks of rows");
  }
  const std::vector<Vec3> origins = ray_origins(receivers, mesh);
  const std::vector<Vec3> vertex_pattern = cosine_pattern(rays_per_vertex, seed);
  const std::vector<Vec3> sensor_pattern = cosine_pattern(rays_per_sensor, seed);
  const std::vector<std::size_t> my_chunks = own.my_blocks();

  using Index = Eigen::SparseMatrix<float, Eigen::RowMajor>::StorageIndex;
  constexpr auto kMaxEntries = static_cast<std::size_t>(std::numeric_limits<Index>::max());
  GatherOperator result;
  result.matrix.resize(static_cast<Eigen::Index>(rows),
                       static_cast<Eigen::Index>(receivers.vertex_count));
  Index* outer = result.matrix.outerIndexPtr();
  // The entries go straight into the matrix's storage, reserved for what a sample of rows
  // predicts (its pages are touched only as rows arrive), so that the rows are never held
  // twice; a window's buffers are all that is held beside it.
  const GatherEntries expected =
      sampled != nullptr
          ? *sampled
          : sample_gather_entries(receivers, mesh, traced, rays_per_vertex, rays_per_sensor, seed);
  const std::size_t my_vertex_rows = own.my_receivers_below(receivers.vertex_count);
  std::size_t capacity =
      static_cast<std::size_t>(
          1.05 *
          (expected.per_vertex_row * static_cast<double>(my_vertex_rows) +
           expected.per_sensor_row * static_cast<double>(own.my_receivers() - my_vertex_rows))) +
      kChunkRows * static_cast<std::size_t>(3 * std::max(rays_per_vertex, rays_per_sensor));
  capacity = std::min(capacity, kMaxEntries);
  result.matrix.resizeNonZeros(static_cast<Eigen::Index>(capacity));

  Progress bar("gather operator", own.my_receivers(), progress);
  tbb::enumerable_thread_specific<RowScratch> scratches(receivers.vertex_count);
  std::vector<ChunkRows> window(
      std::min(window_chunks(), std::max<std::size_t>(1, my_chunks.size())));
  std::size_t entries = 0, next_row = 0;
  for (std::size_t w = 0; w < my_chunks.size(); w += window.size()) {
    const std::size_t n = std::min(window.size(), my_chunks.size() - w);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
      RowScratch& scratch = scratches.local();
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const std::size_t c = my_chunks[w + i];
        const std::size_t first = c * kChunkRows, last = std::min(rows, first + kChunkRows);
        ChunkRows& out = window[i];
        out.row_sizes.clear();
        out.columns.clear();
        out.values.clear();
        for (std::size_t r = first; r < last; ++r) {
          const std::vector<Vec3>& pattern =
              r < receivers.vertex_count ? vertex_pattern : sensor_pattern;
          trace_row(mesh, traced, origins[r], receivers.normals[r], r, pattern, seed, scratch, out);
        }
        bar.advance(last - first);
      }
    });
    // Appended in row order; the rows of other ranks' chunks between are empty.
    for (std::size_t i = 0; i < n; ++i) {
      const ChunkRows& chunk = window[i];
      const std::size_t first = my_chunks[w + i] * kChunkRows;
      if (entries + chunk.columns.size() > kMaxEntries) {
        throw std::invalid_argument("gather operator: more than 2^31 - 1 entries");
      }
      if (entries + chunk.columns.size() > capacity) {
        capacity = std::min(kMaxEntries,
                            std::max(entries + chunk.columns.size(), capacity + capacity / 4));
        result.matrix.resizeNonZeros(static_cast<Eigen::Index>(capacity));
        outer = result.matrix.outerIndexPtr();
      }
      for (; next_row < first; ++next_row) outer[next_row] = static_cast<Index>(entries);
      std::copy(chunk.columns.begin(), chunk.columns.end(),
                result.matrix.innerIndexPtr() + entries);
      std::copy(chunk.values.begin(), chunk.values.end(), result.matrix.valuePtr() + entries);
      for (const std::uint32_t size : chunk.row_sizes) {
        outer[next_row++] = static_cast<Index>(entries);
        entries += size;
      }
    }
  }
  bar.finish();
  for (; next_row < rows; ++next_row) outer[next_row] = static_cast<Index>(entries);
  outer[rows] = static_cast<Index>(entries);
  result.matrix.data().resize(static_cast<Eigen::Index>(entries));
  result.rays = static_cast<std::uint64_t>(receivers.vertex_count) * rays_per_vertex +
                static_cast<std::uint64_t>(receivers.sensor_count) * rays_per_sensor;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relight
