// A thread-safe progress bar on stderr for long phases (reference rendering, later the
// precompute phases). On a terminal it redraws one line; otherwise (CI logs) it prints
// a line every 10%. Silent when disabled.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

namespace relight {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total, bool enabled = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t steps = 1);
  void finish();
  double seconds() const;

 private:
  void draw(std::uint64_t done);

  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool tty_;
  std::atomic<std::uint64_t> done_{0};
  std::atomic<int> last_permille_{-1};
  std::mutex draw_mutex_;
  std::chrono::steady_clock::time_point start_;
  bool finished_ = false;
};

// A line Progress prints when stderr is not a terminal ("LABEL [###...] 40.0% 12.3s"), read
// back by a program that runs this one (the studio's precompute of an uploaded model); nullopt
// for any other line.
struct ProgressLine {
  std::string label;
  double fraction = 0;  // 0..1
};
std::optional<ProgressLine> parse_progress_line(const std::string& line);

}  // namespace relight
