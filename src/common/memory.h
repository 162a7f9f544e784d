// The memory this machine can still give a process: for refusing work that cannot fit before
// starting it (a scene too large for a rank's share of memory is refused before tracing, with
// the numbers).
#pragma once

#include <cstdint>
#include <optional>

namespace relight {

// MemAvailable plus SwapFree from /proc/meminfo, in bytes — what the kernel estimates it can
// give without swapping out others, and the swap beyond it — or less where the process's cgroup
// (a container) allows less; nullopt where /proc/meminfo cannot be read.
std::optional<std::uint64_t> available_memory_bytes();

// What this process holds resident now (/proc/self/statm), in bytes; 0 where it cannot be read.
std::uint64_t resident_bytes();

// The most this process has held resident so far (getrusage's ru_maxrss), in bytes.
std::uint64_t peak_resident_bytes();

}  // namespace relight
