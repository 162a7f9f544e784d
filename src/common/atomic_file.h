// Files are written atomically: the content goes to a temporary name beside the target and is
// renamed over it only when complete, so a crash or a full disk never leaves a half-written file
// where the user's was.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace relight {

// Calls write(tmp) with a temporary path in the target's folder, then renames tmp
// onto target. If write throws, the temporary is removed and the target untouched; a
// failing rename or text write is an InputError naming the target (exit code 2: the
// user chose the path). A SIGTERM, SIGINT or SIGHUP while write runs (Ctrl-C, or mpirun ending
// rank 0 as it writes because another rank died) removes the temporary before the process
// ends as the signal's default action would end it. Pinned by
// tests/store/rlt_atomic_write_test.cpp.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

void write_text_atomically(const std::filesystem::path& target, std::string_view text);

}  // namespace relight
