#include "sources/precompute_memory.h"

#include <cstdio>

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

PrecomputeMemory least_precompute_memory(const Scene& scene, const Receivers& receivers) {
  PrecomputeMemory m;
  m.receivers = receivers.size();
  m.columns =
      scene.luminaires.size() * static_cast<std::uint64_t>(sh_count(scene.precompute.sh_order)) +
      scene.portals.size() * static_cast<std::uint64_t>(sh_count(scene.precompute.portal_sh_order));
  m.bytes = dense_half_copies(scene) * m.receivers * m.columns * sizeof(float) / 2;
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
  return scene.file.string() + ": too large to precompute here: it needs at least " +
         gigabytes(need.bytes) + " (" + std::to_string(need.receivers) + " receivers × " +
         std::to_string(need.columns) + " bounced basis columns × 4 bytes × " + copies +
         " dense copies at its peak), and " + gigabytes(available) + " is available " + where +
         " (MemAvailable + SwapFree)";
}

}  // namespace relight
