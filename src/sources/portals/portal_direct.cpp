#include "sources/portals/portal_direct.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "math/cubemap.h"
#include "math/cubemap_polygon.h"
#include "math/sampling.h"
#include "math/sh.h"

namespace relight {

namespace {

constexpr std::size_t kChunk = 64;  // receivers per unit of parallel work

struct Scratch {
  Scratch(int n, int bases)
      : cells(cubemap_texel_count(n), 0.0),
        marked(cubemap_texel_count(n), 0),
        sh(static_cast<std::size_t>(bases)),
        basis(static_cast<std::size_t>(bases)) {}
  std::vector<double> cells;
  std::vector<std::uint8_t> marked;
  std::vector<std::uint32_t> touched, listed;
  std::vector<Vec3> piece;
  CubemapPolygonScratch polygon;
  PieceCones cones;
  std::vector<double> sh, basis;
  std::vector<std::pair<Vec3, double>> hits;  // of the cell being traced
  CubemapEncodeScratch encode;
};

struct ChunkOutput {
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint32_t> sizes;
  std::vector<EncodedReceiver> encoded;
  Vec3 flow{0, 0, 0};  // Σ weight · direction: where the light comes from
  std::uint64_t rays = 0, samples = 0;
};

// The directions through one cubemap cell: k×k jittered sub-cells, each with its solid angle
// (tabulated for the N·k grid of a face); cells on the window's outline are traced again on
// a grid kEdgeRefinement times finer.
constexpr int kEdgeRefinement = 4;

struct SubcellGrid {
  int k = 1;
  std::vector<double> omega;  // (N·k)² per face, row-major
};

struct CellGrid {
  int n = 0;
  SubcellGrid coarse, fine;
};

CellGrid make_cell_grid(int n, int samples_per_cell) {
  CellGrid g;
  g.n = n;
  g.coarse.k = std::max(1, static_cast<int>(std::lround(std::sqrt(double(samples_per_cell)))));
  g.coarse.omega = cubemap_solid_angles(n * g.coarse.k);
  g.fine.k = g.coarse.k * kEdgeRefinement;
  g.fine.omega = cubemap_solid_angles(n * g.fine.k);
  return g;
}

// Whether a direction from a receiver passes through the portal before any other portal: by
// the pieces' cones where the portal has few edges (and, when the scene has other portals, a
// ray that must meet this one's triangles first), else by that ray alone.
struct PortalPass {
  const TracedScene* traced = nullptr;
  const std::vector<std::uint8_t>* in_portal = nullptr;
  bool by_cones = false;
  bool other_portals = false;

  bool operator()(Vec3 origin, Vec3 dir, const PieceCones& cones, ChunkOutput& out) const {
    if (by_cones && !cones.contains(dir)) return false;
    if (by_cones && !other_portals) return true;
    ++out.rays;
    const RayHit window = traced->portals.intersect({origin, dir});
    return window.hit() && (*in_portal)[window.triangle];
  }
};

// Step 1 (no rays): the cells the portal covers seen from `origin`, in front of the receiver's
// tangent plane (math/cubemap_polygon.h over its convex pieces), each listed once in
// scratch.touched. Returns false when none.
bool candidate_cells(Vec3 origin, Vec3 normal, const std::vector<PortalPiece>& pieces, int n,
                     Scratch& scratch) {
  for (const PortalPiece& piece : pieces) {
    scratch.piece.clear();
    for (const Vec3& v : piece) scratch.piece.push_back(v - origin);
    scratch.listed.clear();
    cubemap_polygon_texels(n, scratch.piece, normal, scratch.polygon, scratch.listed);
    for (const std::uint32_t cell : scratch.listed) {
      if (!scratch.marked[cell]) {
        scratch.marked[cell] = 1;
        scratch.touched.push_back(cell);
      }
    }
  }
  return !scratch.touched.empty();
}

// One cell on one sub-cell grid: the directions that pass this portal first and then reach
// the exterior, as (direction, cos θ · Ω_sub) in scratch.hits.
void trace_cell(Vec3 origin, Vec3 normal, CubemapTexel c, int n, const SubcellGrid& grid,
                const PortalPass& pass, const TracedScene& traced, Pcg32& rng, Scratch& scratch,
                ChunkOutput& out) {
  const int k = grid.k, m = n * k;
  scratch.hits.clear();
  for (int b = 0; b < k; ++b) {
    for (int a = 0; a < k; ++a) {
      const int si = c.i * k + a, sj = c.j * k + b;
      const Vec3 dir =
          cubemap_direction({c.face, (si + rng.next_double()) / m, (sj + rng.next_double()) / m});
      const double cos_r = dot(normal, dir);
      if (cos_r <= 0) continue;
      ++out.samples;
      if (!pass(origin, dir, scratch.cones, out)) continue;
      ++out.rays;
      if (traced.opaque.occluded({origin, dir})) continue;  // before or past the portal
      scratch.hits.push_back({dir, cos_r * grid.omega[static_cast<std::size_t>(sj) * m + si]});
    }
  }
}

// Step 2: t_c of every candidate cell from k×k jittered directions through it, each checked
// to pass through the portal (the first portal it meets must be this one) and traced once
// against opaque geometry to infinity (visibility and backward occlusion together). A cell
// wholly inside the window's outline gets ∫_c cos θ dω over its unoccluded part up to the
// sub-cell quadrature, with no sampling noise from the portal's outline — a sun in the middle
// of the window lights neighbouring receivers alike. A cell is inside the outline when the
// directions of its four corners pass the portal (exact for a convex window: the gnomonic
// projection keeps cells and the window's outline straight-edged); every other cell is traced
// on a grid kEdgeRefinement times finer, so the outline costs sampling noise only on that
// finer scale.
void trace_cells(Vec3 origin, Vec3 normal, std::size_t receiver, const CellGrid& grid,
                 const PortalPass& pass, const TracedScene& traced, const PortalDirectSettings& s,
                 Scratch& scratch, ChunkOutput& out) {
  Pcg32 rng(s.seed ^ 0x5bd1e995u, receiver);
  std::size_t kept = 0;
  for (const std::uint32_t cell : scratch.touched) {
    scratch.marked[cell] = 0;
    const CubemapTexel c = cubemap_texel_from_index(grid.n, cell);
    int corners_in = 0;
    for (int corner = 0; corner < 4; ++corner) {
      const int ci = c.i + (corner & 1), cj = c.j + (corner >> 1);
      const Vec3 dir = cubemap_direction({c.face, double(ci) / grid.n, double(cj) / grid.n});
      corners_in += pass(origin, dir, scratch.cones, out) ? 1 : 0;
    }
    // All corners in: inside. Otherwise the outline crosses the cell, or the cell holds a
    // corner of the window: finely traced.
    trace_cell(origin, normal, c, grid.n, corners_in == 4 ? grid.coarse : grid.fine, pass, traced,
               rng, scratch, out);
    double sum = 0;
    for (const auto& [dir, weight] : scratch.hits) {
      sum += weight;
      sh_eval(s.sh_order, dir, scratch.basis);
      for (std::size_t i = 0; i < scratch.sh.size(); ++i)
        scratch.sh[i] += weight * scratch.basis[i];
      out.flow = out.flow + dir * weight;
    }
    if (sum > 0) {
      scratch.cells[cell] = sum;
      scratch.touched[kept++] = cell;
    }
  }
  scratch.touched.resize(kept);
}

// Fills scratch.cells (non-zero cells listed in scratch.touched) and scratch.sh.
void sample_receiver(Vec3 point, Vec3 normal, std::size_t receiver, const PortalGeometry& portal,
                     const CellGrid& grid, const PortalPass& pass, const TracedScene& traced,
                     const PortalDirectSettings& s, Scratch& scratch, ChunkOutput& out) {
  std::fill(scratch.sh.begin(), scratch.sh.end(), 0.0);
  const Vec3 origin = offset_from_surface(point, normal);
  if (!candidate_cells(origin, normal, portal.pieces, grid.n, scratch)) return;
  if (pass.by_cones) scratch.cones.reset(origin, portal.pieces);
  trace_cells(origin, normal, receiver, grid, pass, traced, s, scratch, out);
}

// What the portal's summary needs of every chunk, the records staying with their rank
// (engine/ranks.h: a chunk is one of the ranks' blocks).
struct ChunkSummary {
  CubemapEncodingStats stats;
  Vec3 flow{0, 0, 0};
  std::uint64_t rays = 0, samples = 0;
};

ChunkSummary summary_of(const ChunkOutput& chunk) {
  ChunkSummary out{{}, chunk.flow, chunk.rays, chunk.samples};
  for (const EncodedReceiver& e : chunk.encoded) add_receiver(out.stats, e);
  return out;
}

// Every rank's chunks' summaries from theirs.
void share_summaries(const RankShares& ranks, std::vector<ChunkSummary>& summaries) {
  share_block_records(
      ranks,
      [&](std::size_t c, std::vector<std::uint8_t>& bytes) {
        put_values<ChunkSummary>(bytes, std::span(&summaries[c], 1));
      },
      [&](std::size_t c, std::span<const std::uint8_t> theirs, std::size_t& at) {
        summaries[c] = take_values<ChunkSummary>(theirs, at).at(0);
      });
}

}  // namespace

PortalDirect compute_portal_direct(const Receivers& receivers, const std::vector<Vec3>& ray_points,
                                   const std::vector<std::uint8_t>& skip, const PreparedMesh& mesh,
                                   const TracedScene& traced, const PortalGeometry& portal,
                                   const PortalDirectSettings& settings, bool progress,
                                   const RankShares* ranks) {
  const int n = settings.face_size;
  if (n < 1 || (n & (n - 1)) != 0 || settings.sh_order < 1 || settings.samples_per_cell < 1) {
    throw std::invalid_argument("portal direct: bad settings");
  }
  if (ray_points.size() != receivers.size() || skip.size() != receivers.size() ||
      portal.triangles.empty()) {
    throw std::invalid_argument("portal direct: inputs do not match");
  }
  const CellGrid grid = make_cell_grid(n, settings.samples_per_cell);
  std::vector<std::uint8_t> in_portal(mesh.triangles.size(), 0);
  for (std::uint32_t t : portal.triangles) in_portal[t] = 1;
  std::size_t edges = 0;
  for (const PortalPiece& piece : portal.pieces) edges += piece.size();
  const PortalPass pass{&traced, &in_portal, edges <= settings.max_cone_edges,
                        traced.portals.triangle_count() > portal.triangles.size()};
  const int bases = sh_count(settings.sh_order);
  const std::size_t rows = receivers.size();
  const std::size_t chunk_count = (rows + kChunk - 1) / kChunk;
  const RankShares own = ranks != nullptr ? *ranks : single_process_shares(rows, kChunk);
  if (own.receivers != rows || own.block != kChunk) {
    throw std::invalid_argument("portal direct: the ranks' blocks are not its chunks of receivers");
  }
  PortalDirect result;
  result.face_size = n;
  result.sh_columns = Eigen::MatrixXf::Zero(static_cast<Eigen::Index>(rows), bases);
  std::vector<ChunkOutput> chunks(chunk_count);
  tbb::enumerable_thread_specific<Scratch> scratches(n, bases);
  Progress bar("portal \"" + portal.name + "\" direct", own.my_receivers(), progress);
  const std::vector<std::size_t> my_chunks = own.my_blocks();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, my_chunks.size()), [&](const auto& range) {
    Scratch& scratch = scratches.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const std::size_t c = my_chunks[i];
      ChunkOutput& out = chunks[c];
      const std::size_t first = c * kChunk, last = std::min(rows, first + kChunk);
      for (std::size_t r = first; r < last; ++r) {
        scratch.touched.clear();
        if (!skip[r]) {
          sample_receiver(ray_points[r], receivers.normals[r], r, portal, grid, pass, traced,
                          settings, scratch, out);
        }
        const std::size_t before = out.bytes.size();
        if (scratch.touched.empty()) {
          out.bytes.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kEmpty));
          out.encoded.push_back({.kind = CubemapCodeKind::kEmpty,
                                 .bytes = 1,
                                 .pulse_bytes = 1,
                                 .haar_bytes = 1,
                                 .runs_bytes = 1,
                                 .rectangles_bytes = cubemap_rectangles_fit(n) ? 1u : 0u});
        } else {
          out.encoded.push_back(
              encode_receiver_cubemap(n, scratch.cells, {}, out.bytes, scratch.encode));
          for (int b = 0; b < bases; ++b) {
            result.sh_columns(static_cast<Eigen::Index>(r), b) =
                static_cast<float>(scratch.sh[static_cast<std::size_t>(b)]);
          }
          for (std::uint32_t cell : scratch.touched) scratch.cells[cell] = 0;
        }
        out.sizes.push_back(static_cast<std::uint32_t>(out.bytes.size() - before));
      }
      bar.advance(last - first);
    }
  });
  bar.finish();
  // Each rank keeps its chunks' records and SH columns (the bounce needs its own rows, rank 0
  // gathers the records as it writes the file); the summaries are shared, and summed in the
  // chunks' order as one process sums them.
  std::vector<ChunkSummary> summaries(chunk_count);
  for (const std::size_t c : own.my_blocks()) summaries[c] = summary_of(chunks[c]);
  if (!own.alone()) share_summaries(own, summaries);
  result.offsets.reserve(own.my_receivers() + 1);
  result.offsets.push_back(0);
  for (const std::size_t c : own.my_blocks()) {
    const ChunkOutput& chunk = chunks[c];
    result.records.insert(result.records.end(), chunk.bytes.begin(), chunk.bytes.end());
    for (std::uint32_t size : chunk.sizes) result.offsets.push_back(result.offsets.back() + size);
  }
  Vec3 flow{0, 0, 0};
  for (const ChunkSummary& summary : summaries) {
    add_stats(result.stats, summary.stats);
    flow = flow + summary.flow;
    result.rays += summary.rays;
    result.samples += summary.samples;
  }
  // The light travels −flow; the portal's outward side is the side the flow points to.
  if (length(portal.normal) > 0) {
    result.outward = dot(flow, portal.normal) >= 0 ? portal.normal : portal.normal * -1.0;
  } else {
    result.outward = length(flow) > 0 ? normalize(flow) : Vec3{0, 1, 0};
  }
  return result;
}

}  // namespace relight
