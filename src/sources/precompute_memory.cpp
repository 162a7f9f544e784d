#include "sources/precompute_memory.h"

#include <cstdio>

#include "math/sh.h"

namespace relight {

namespace {

// The direct columns, three channels of the bounce's result, three channels packed.
constexpr std::uint64_t kDenseCopies = 7;

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
  m.bytes = kDenseCopies * m.receivers * m.columns * sizeof(float);
  return m;
}

std::string memory_refusal(const Scene& scene, const PrecomputeMemory& need,
                           std::uint64_t available, int ranks_here) {
  if (need.bytes <= available) return {};
  std::string where =
      ranks_here > 1 ? "for each of the " + std::to_string(ranks_here) + " ranks on this machine"
                     : "on this machine";
  return scene.file.string() + ": too large to precompute here: it needs at least " +
         gigabytes(need.bytes) + " (" + std::to_string(need.receivers) + " receivers × " +
         std::to_string(need.columns) + " bounced basis columns × 4 bytes × " +
         std::to_string(kDenseCopies) + " dense copies at its peak), and " + gigabytes(available) +
         " is available " + where + " (MemAvailable + SwapFree)";
}

}  // namespace relight
