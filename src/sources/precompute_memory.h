// The precompute's peak memory, predicted before its long work: `relight info` prints it and
// `relight precompute` refuses, with the numbers, a scene whose prediction exceeds the memory it
// may use (a rank's share of its machine, or a set limit), instead of being killed part way.
//
// What is held is known from the scene's sizes once the mesh is prepared and its Embree scenes
// are built — everything then resident is measured, not modelled — except the gather operator's
// entries, which a traced sample of its rows gives (engine/gather_operator.h
// sample_gather_entries). With K bounced basis columns (a luminaire's sh_order², a portal's
// portal_sh_order²) and M = a rank's receivers × K floats, Mv its vertex rows' part, the phases
// after the gather hold, beside the resident part and the gather operator G:
//   - the gather build: G, one window of traced rows and each thread's row accumulator;
//   - the bounce (engine/bounce_solver.cpp): the direct columns M, their vertex rows Mv
//     row-major, the channels solved M each, the channel being solved (its gathered light M, its
//     reflected light — every vertex's on several ranks — and its column-major copy M);
//   - the packing: the direct columns, three channels and their packed copy (3M as floats, 1.5M
//     as binary16, converted from a float copy of the largest source's columns);
//   - the portals' encoded cubemaps from their direct phase on, the luminaires' exact-direct
//     geometry and the near-field emitters' SH transfer;
//   - the visibility cuts, last, beside the packed transfer: their height-encoded stores (sized by
//     their prediction) and a window of cuts being encoded.
// Pinned by tests/cli/precompute_memory_test.cpp (within 25 % of the measured peak on rooms of
// several sizes and kinds of source) and tests/cli/mpi_precompute_test.cpp (refusals).
#pragma once

#include <cstdint>
#include <string>

#include "engine/gather_operator.h"
#include "engine/receivers.h"
#include "scene/scene.h"

namespace relight {

struct PrecomputeMemory {
  std::uint64_t bytes = 0;     // the predicted peak of the rank with the most
  std::uint64_t resident = 0;  // held when predicted: the program, scene, mesh, Embree's BVH
  std::uint64_t gather = 0;    // the gather operator's rows of that rank
  std::uint64_t dense = 0;     // the basis columns' matrices at their peak
  std::uint64_t sources = 0;   // the direct light kept: cubemaps, geometry, near-field SH
  std::uint64_t cuts = 0;      // the visibility cuts
  std::string peak_phase;      // "gather operator", "bounces", "pack" or "visibility cuts"
  std::uint64_t receivers = 0, columns = 0;
  std::uint64_t ranks = 1, share = 0;  // share: the receivers of the rank with the most
};

// On `ranks` ranks (engine/ranks.h), each holds the gather rows and dense matrices of its share
// of the receivers only, and during the bounce the reflected light of every vertex. `resident`:
// what the process holds now, with the mesh prepared and traced; `cuts`: the visibility cuts'
// bytes and their window's (sources/environment/cuts_precompute.h predict_cuts), 0 without a
// top-level environment.
PrecomputeMemory predict_precompute_memory(const Scene& scene, const Receivers& receivers,
                                           const GatherEntries& entries, std::uint64_t cuts,
                                           std::uint64_t resident, int ranks = 1);

// Empty when `need` fits in `available` bytes (`limit_source` says where that figure comes from:
// the machine's free memory, a rank's share of it, --memory-limit); else the refusal,
// "SCENE: reason" with the numbers.
std::string memory_refusal(const Scene& scene, const PrecomputeMemory& need,
                           std::uint64_t available, const std::string& limit_source);

// "N MB" and its parts, as `relight info` prints it after "memory estimate: ".
std::string memory_summary(const PrecomputeMemory& need);

}  // namespace relight
