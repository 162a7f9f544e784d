#include "sources/precompute_memory.h"

#include <algorithm>
#include <cstdio>

#include "engine/transfer_blocks.h"
#include "math/sh.h"

namespace relight {

namespace {

// The direct columns and three channels of the bounce's result as floats, and three channels
// packed: as floats (fp32 storage) or binary16 (fp16), in halves of a float matrix.
std::uint64_t dense_half_copies(const Scene& scene) {
  return 2 * 4 + (scene.precompute.storage == "fp16" ? 3 : 6);
}

std::string gigabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) * 1e-9);
  return text;
}

}  // namespace

PrecomputeMemory least_precompute_memory(const Scene& scene, const Receivers& receivers,
                                         int ranks) {
  PrecomputeMemory m;
  m.receivers = receivers.size();
  m.ranks = static_cast<std::uint64_t>(std::max(ranks, 1));
  // A rank's share, rounded up to whole blocks of the transfer.
  m.share = std::min<std::uint64_t>(m.receivers,
                                    (block_count(m.receivers) + m.ranks - 1) / m.ranks * kBlock);
  m.columns =
      scene.luminaires.size() * static_cast<std::uint64_t>(sh_count(scene.precompute.sh_order)) +
      scene.portals.size() * static_cast<std::uint64_t>(sh_count(scene.precompute.portal_sh_order));
  const std::uint64_t packing = dense_half_copies(scene) * m.share * m.columns * sizeof(float) / 2;
  // The bounce: every vertex's reflected light beside the rank's direct columns, their vertex
  // rows and its gathered rows (only on several ranks can this exceed the packing's peak).
  const std::uint64_t bounce = (receivers.vertex_count + 3 * m.share) * m.columns * sizeof(float);
  m.bytes = std::max(packing, bounce);
  return m;
}

std::string memory_refusal(const Scene& scene, const PrecomputeMemory& need,
                           std::uint64_t available, int ranks_here) {
  if (need.bytes <= available) return {};
  const std::uint64_t halves = dense_half_copies(scene);
  const std::string copies = std::to_string(halves / 2) + (halves % 2 != 0 ? ".5" : "");
  std::string where =
      ranks_here > 1 ? "for each of the " + std::to_string(ranks_here) + " ranks on this machine"
                     : "on this machine";
  const std::string receivers = need.ranks > 1 ? "a rank's " + std::to_string(need.share) + " of " +
                                                     std::to_string(need.receivers) + " receivers"
                                               : std::to_string(need.receivers) + " receivers";
  return scene.file.string() + ": too large to precompute here: it needs at least " +
         gigabytes(need.bytes) + " (" + receivers + " × " + std::to_string(need.columns) +
         " bounced basis columns × 4 bytes × " + copies + " dense copies at its peak" +
         (need.ranks > 1 ? ", or the bounce's reflected light of every vertex" : "") + "), and " +
         gigabytes(available) + " is available " + where + " (MemAvailable + SwapFree)";
}

}  // namespace relight
