#include "common/atomic_file.h"

#include "common/input_error.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <stdexcept>
#include <system_error>

#include <signal.h>
#include <unistd.h>

namespace relight {

namespace fs = std::filesystem;

namespace {

// The temporaries being written, for the signal handler: fixed slots, since a handler may
// neither allocate nor lock. A write beyond kSlots at once goes unguarded.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
char g_paths[kSlots][kPathBytes];
std::atomic<bool> g_used[kSlots];
constexpr std::array<int, 3> kSignals{SIGTERM, SIGINT, SIGHUP};
std::once_flag g_install;

extern "C" void remove_temporaries_and_end(int signal_number) {
  for (int i = 0; i < kSlots; ++i) {
    if (g_used[i].load()) ::unlink(g_paths[i]);
  }
  // The default action, as if nothing had been caught.
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

// Installs the handler for signals whose action is the default (one installed by someone else,
// or ignored, is left as it is).
void install_handler() {
  for (const int s : kSignals) {
    struct sigaction old {};
    if (::sigaction(s, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_end;
    sigemptyset(&action.sa_mask);
    ::sigaction(s, &action, nullptr);
  }
}

// Registers `tmp` for the handler while it lives.
class GuardedTemporary {
 public:
  explicit GuardedTemporary(const fs::path& tmp) {
    std::call_once(g_install, install_handler);
    const std::string text = tmp.string();
    if (text.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
      bool expected = false;
      // A slot is claimed, filled, then published: the handler reads only published slots.
      if (!claimed_[i].compare_exchange_strong(expected, true)) continue;
      std::memcpy(g_paths[i], text.c_str(), text.size() + 1);
      g_used[i].store(true);
      slot_ = i;
      return;
    }
  }
  ~GuardedTemporary() {
    if (slot_ < 0) return;
    g_used[slot_].store(false);
    claimed_[slot_].store(false);
  }
  GuardedTemporary(const GuardedTemporary&) = delete;
  GuardedTemporary& operator=(const GuardedTemporary&) = delete;

 private:
  static inline std::atomic<bool> claimed_[kSlots];
  int slot_ = -1;
};

}  // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::random_device entropy;
  // Keep the extension last: image writers choose the format from it.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(entropy());
  name += target.extension().string();
  const fs::path tmp = folder / name;
  const GuardedTemporary guard(tmp);
  try {
    write(tmp);
    fs::rename(tmp, target);
  } catch (const fs::filesystem_error& e) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    fail_input(target.string(), "cannot write: " + e.code().message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void write_text_atomically(const fs::path& target, std::string_view text) {
  write_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) fail_input(target.string(), std::string("cannot write: ") + std::strerror(errno));
  });
}

}  // namespace relight
