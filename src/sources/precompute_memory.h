// The memory a precompute cannot do without, known before any ray is traced (a scene too large for
// a rank's share of memory is refused before tracing, with the numbers). Every source's bounced
// basis columns (a luminaire's sh_order², a portal's portal_sh_order²) are dense over the
// receivers, 4 bytes a value, and at the peak — the interreflected columns packed into each
// source's blocks while the bounce's result and the direct columns are still held — seven
// receivers × columns float matrices live at once: the direct columns, three channels of the
// bounce's result, three channels packed (5.5 with binary16 storage, whose three packed channels
// take half). The gather operator, the cubemaps and the direct geometry come on top (their sizes
// are known only once traced), so this is a lower bound: a scene it refuses cannot fit; one it
// passes may still not. Pinned by tests/cli/mpi_precompute_test.cpp (a scene that needs more than
// the machine has).
#pragma once

#include <cstdint>
#include <string>

#include "engine/receivers.h"
#include "scene/scene.h"

namespace relight {

struct PrecomputeMemory {
  std::uint64_t bytes = 0;  // the least the peak of one rank holds
  std::uint64_t receivers = 0, columns = 0;
  std::uint64_t ranks = 1, share = 0;  // share: the receivers of the rank with the most
};

// On `ranks` ranks (engine/ranks.h), each holds the dense matrices of its share of the
// receivers only, and during the bounce the reflected light of every vertex (its own and those
// its rows read from other ranks: in a room, nearly all).
PrecomputeMemory least_precompute_memory(const Scene& scene, const Receivers& receivers,
                                         int ranks = 1);

// Empty when `need` fits in `available` bytes (a rank's share of its machine, `ranks_here` ranks
// sharing it); else the refusal, "SCENE: reason" with the numbers.
std::string memory_refusal(const Scene& scene, const PrecomputeMemory& need,
                           std::uint64_t available, int ranks_here);

}  // namespace relight
