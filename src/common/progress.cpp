#include "common/progress.h"

#include <cstdio>
#include <cstdlib>

#include <unistd.h>

namespace relight {

Progress::Progress(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      enabled_(enabled),
      tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_) draw(0);
}

Progress::~Progress() {
  finish();
}

double Progress::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::advance(std::uint64_t steps) {
  const std::uint64_t done = done_.fetch_add(steps) + steps;
  if (!enabled_) return;
  const int step = tty_ ? 5 : 100;  // redraw every 0.5% on a terminal, 10% in logs
  const int permille = static_cast<int>(1000 * std::min(done, total_) / total_);
  int last = last_permille_.load();
  if (permille / step == last / step) return;
  if (!last_permille_.compare_exchange_strong(last, permille)) return;
  draw(done);
}

void Progress::draw(std::uint64_t done) {
  const std::lock_guard<std::mutex> lock(draw_mutex_);
  const double fraction = static_cast<double>(std::min(done, total_)) / static_cast<double>(total_);
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(filled, '#');
  bar.resize(kWidth, '.');
  if (tty_) {
    std::fprintf(stderr, "\r%-24s [%s] %5.1f%% %6.1fs", label_.c_str(), bar.c_str(), 100 * fraction,
                 seconds());
  } else {
    std::fprintf(stderr, "%-24s [%s] %5.1f%% %6.1fs\n", label_.c_str(), bar.c_str(), 100 * fraction,
                 seconds());
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  if (last_permille_.load() < 1000) draw(total_);
  if (tty_) std::fputc('\n', stderr);
}

std::optional<ProgressLine> parse_progress_line(const std::string& line) {
  const std::size_t open = line.find(" [");
  const std::size_t close = line.find("] ", open == std::string::npos ? 0 : open);
  if (open == std::string::npos || close == std::string::npos) return std::nullopt;
  if (line.find_first_not_of("#.", open + 2) != close) return std::nullopt;
  const char* number = line.c_str() + close + 2;
  char* end = nullptr;
  const double percent = std::strtod(number, &end);
  if (end == number || *end != '%' || !(percent >= 0 && percent <= 100)) return std::nullopt;
  const std::size_t last = line.find_last_not_of(' ', open);
  return ProgressLine{line.substr(0, last == std::string::npos ? 0 : last + 1), percent / 100};
}

}  // namespace relight
