// Builds the gather operator of the interreflection engine (see gather_operator.h): rows are traced
// independently in parallel (oneTBB, in fixed chunks of receivers), each row's hits are merged per
// vertex in a per-thread accumulator and appended to its chunk's own buffers, and the rows are then
// copied into one compressed row-major matrix — no lock is taken per ray or per row, and the result
// does not depend on thread scheduling.
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

}  // namespace

GatherOperator build_gather_operator(const Receivers& receivers, const PreparedMesh& mesh,
                                     const TracedScene& traced, int rays_per_vertex,
                                     int rays_per_sensor, std::uint64_t seed, bool progress,
                                     const RankShares* ranks) {
  if (rays_per_vertex < 1 || rays_per_sensor < 1) {
    throw std::invalid_argument("gather operator: rays per receiver must be at least 1");
  }
  if (receivers.vertex_count != mesh.positions.size() ||
      receivers.normals.size() != receivers.size()) {
    throw std::invalid_argument("gather operator: receivers do not match the prepared mesh");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::size_t rows = receivers.size();
  const std::size_t chunk_count = (rows + kChunkRows - 1) / kChunkRows;
  std::vector<ChunkRows> chunks(chunk_count);
  const RankShares own = ranks != nullptr ? *ranks : single_process_shares(rows, kChunkRows);
  if (own.receivers != rows || own.block != kChunkRows) {
    throw std::invalid_argument("gather operator: the ranks' blocks are not its chunks of rows");
  }
  const std::vector<Vec3> points = receiver_ray_points(receivers, mesh);
  std::vector<Vec3> origins(points.size());
  for (std::size_t r = 0; r < points.size(); ++r) {
    origins[r] = offset_from_surface(points[r], receivers.normals[r]);
  }
  const std::vector<Vec3> vertex_pattern = cosine_pattern(rays_per_vertex, seed);
  const std::vector<Vec3> sensor_pattern = cosine_pattern(rays_per_sensor, seed);
  const std::vector<std::size_t> my_chunks = own.my_blocks();
  Progress bar("gather operator", own.my_receivers(), progress);
  tbb::enumerable_thread_specific<RowScratch> scratches(receivers.vertex_count);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, my_chunks.size()), [&](const auto& range) {
    RowScratch& scratch = scratches.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const std::size_t c = my_chunks[i];
      const std::size_t first = c * kChunkRows, last = std::min(rows, first + kChunkRows);
      ChunkRows& out = chunks[c];
      out.row_sizes.reserve(last - first);
      for (std::size_t r = first; r < last; ++r) {
        const std::vector<Vec3>& pattern =
            r < receivers.vertex_count ? vertex_pattern : sensor_pattern;
        trace_row(mesh, traced, origins[r], receivers.normals[r], r, pattern, seed, scratch, out);
      }
      bar.advance(last - first);
    }
  });
  bar.finish();

  // Assemble: row offsets by a prefix sum, then every chunk copies into its own span.
  using Index = Eigen::SparseMatrix<float, Eigen::RowMajor>::StorageIndex;
  std::vector<std::size_t> chunk_offsets(chunk_count + 1, 0);
  for (std::size_t c = 0; c < chunk_count; ++c) {
    chunk_offsets[c + 1] = chunk_offsets[c] + chunks[c].columns.size();
  }
  const std::size_t nonzeros = chunk_offsets.back();
  if (nonzeros > static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
    throw std::invalid_argument("gather operator: more than 2^31 - 1 entries");
  }
  GatherOperator result;
  result.matrix.resize(static_cast<Eigen::Index>(rows),
                       static_cast<Eigen::Index>(receivers.vertex_count));
  result.matrix.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  Index* outer = result.matrix.outerIndexPtr();
  Index* inner = result.matrix.innerIndexPtr();
  float* values = result.matrix.valuePtr();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunk_count), [&](const auto& range) {
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      const ChunkRows& chunk = chunks[c];
      std::size_t offset = chunk_offsets[c];
      // Another rank's chunk has no rows here: its rows are empty.
      for (std::size_t i = 0; i < std::min(kChunkRows, rows - c * kChunkRows); ++i) {
        outer[c * kChunkRows + i] = static_cast<Index>(offset);
        if (i < chunk.row_sizes.size()) offset += chunk.row_sizes[i];
      }
      std::copy(chunk.columns.begin(), chunk.columns.end(), inner + chunk_offsets[c]);
      std::copy(chunk.values.begin(), chunk.values.end(), values + chunk_offsets[c]);
    }
  });
  outer[rows] = static_cast<Index>(nonzeros);
  result.rays = static_cast<std::uint64_t>(receivers.vertex_count) * rays_per_vertex +
                static_cast<std::uint64_t>(receivers.sensor_count) * rays_per_sensor;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace relight
