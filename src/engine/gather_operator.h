// The sparse gather operator G of the interreflection engine: the one piece of ray tracing every
// light source's indirect transfer shares. Row r (a receiver: vertices first, then sensors) holds
// where M cosine-distributed rays from r land: a ray that hits the front side of triangle t at
// barycentrics (b0, b1, b2) adds b_k / M to G[r, t_k]; misses, back sides (they absorb) and portals
// (openings: light arriving through them is the portal transfer's job) add nothing. Columns are
// mesh vertices.
//
// With irradiance E per vertex and luminance L = ρ/π · E, the irradiance reflected onto r
// is π · mean(L over the cosine-distributed rays) = (G · diag(ρ) · E)[r]: G is the
// point-to-vertex-basis form factor matrix. Dobashi et al. 1995 (Dobashi et al. 1995,
// Eq. 14–17) computes the form factors F_ij between patches once and runs one radiosity
// solve per SH basis; Yue et al. 2009 (§4.1.1) shoots a photon map per
// basis function and final-gathers each. Here the rays are traced once, for all bases and
// all bounces, and every basis column then bounces through the same sparse matrix
// (bounce_solver.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/SparseCore>

#include "engine/ranks.h"
#include "engine/receivers.h"
#include "scene/mesh_preparation.h"
#include "trace/traced_scene.h"

namespace relight {

struct GatherOperator {
  // receivers × mesh vertices; each row sums to the fraction of its rays that reached a
  // front face (1 inside a closed room, less where rays escape through openings).
  Eigen::SparseMatrix<float, Eigen::RowMajor> matrix;
  std::uint64_t rays = 0;  // rays traced to build it
  double seconds = 0;      // wall-clock time to build it
};

// The mean entries of a vertex row and of a sensor row of the operator, from tracing a few hundred
// evenly spaced vertex rows and a few dozen sensor rows exactly as build_gather_operator traces
// them: what the matrix will hold, known for a fraction of its rays (sources/precompute_memory.h
// predicts the precompute's memory from it, and the build reserves its storage by it).
struct GatherEntries {
  double per_vertex_row = 0, per_sensor_row = 0;
};
GatherEntries sample_gather_entries(const Receivers& receivers, const PreparedMesh& mesh,
                                    const TracedScene& traced, int rays_per_vertex,
                                    int rays_per_sensor, std::uint64_t seed);

// What build_gather_operator holds beside the matrix it fills, at most: a window of traced rows
// (of the larger kind) and each thread's row accumulator over the vertices.
std::uint64_t gather_build_scratch_bytes(const GatherEntries& entries, std::size_t vertices);

// Shoots `rays_per_receiver` cosine-distributed rays from every receiver (a scrambled
// (0,2)-sequence per receiver, Kollig & Keller 2002, deterministic from `seed` and the
// receiver's index, independent of thread scheduling). Receivers must be those of `mesh`
// (vertex_count == mesh vertex count) and `traced` built from the same mesh. Throws
// std::invalid_argument for rays_per_receiver < 1, mismatched inputs or a matrix with more
// than 2^31 - 1 entries. With several `ranks` (engine/ranks.h; shares on multiples of kBlock),
// this process traces its own share's rows and keeps only those (the other rows empty): the
// bounce reads its own rows, and rank 0 gathers the rest as it writes the file; `rays` counts
// every rank's. `sampled`: sample_gather_entries of the same inputs, when the caller has it (the
// build reserves its storage by it; it samples itself otherwise).
GatherOperator build_gather_operator(const Receivers& receivers, const PreparedMesh& mesh,
                                     const TracedScene& traced, int rays_per_vertex,
                                     int rays_per_sensor, std::uint64_t seed, bool progress,
                                     const RankShares* ranks = nullptr,
                                     const GatherEntries* sampled = nullptr);

}  // namespace relight
