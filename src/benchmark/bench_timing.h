// What every `relight bench` figure is made of: wall-clock milliseconds of a frame, repeated,
// and their median (the machines are shared: the median of many frames, not one).
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace relight {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Milliseconds of f(i) for i = 0 .. frames − 1.
template <class F>
std::vector<double> time_ms(int frames, F&& f) {
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    f(i);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  return ms;
}

}  // namespace relight
