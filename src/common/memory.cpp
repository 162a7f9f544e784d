#include "common/memory.h"

#include <sys/resource.h>

#include <fstream>
#include <sstream>
#include <string>

namespace relight {

std::optional<std::uint64_t> available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  if (!in) return std::nullopt;
  std::optional<std::uint64_t> available, swap;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string name, unit;
    std::uint64_t value = 0;
    if (!(fields >> name >> value)) continue;
    fields >> unit;
    const std::uint64_t bytes = unit == "kB" ? value * 1024 : value;
    if (name == "MemAvailable:") available = bytes;
    if (name == "SwapFree:") swap = bytes;
  }
  if (!available) return std::nullopt;
  return *available + swap.value_or(0);
}

std::uint64_t peak_resident_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;  // kilobytes on Linux
}

}  // namespace relight
