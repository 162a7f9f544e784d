// The fast path against `relight reference` as the accuracy tests measure it: sensor values
// and images' block luminance, relative to the reference's.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "image/image.h"

namespace relight::testing {

struct Agreement {
  double mean = 0, worst = 1;  // relative differences; worst 1 when nothing was compared
};

// |fast − truth| / truth value by value; every truth must be positive, the sizes equal.
inline Agreement relative_agreement(const std::vector<double>& fast,
                                    const std::vector<double>& truth) {
  EXPECT_EQ(fast.size(), truth.size());
  if (truth.size() != fast.size() || fast.empty()) return {};
  Agreement a{0, 0};
  for (std::size_t i = 0; i < fast.size(); ++i) {
    EXPECT_GT(truth[i], 0) << i;
    const double e = std::abs(fast[i] - truth[i]) / truth[i];
    a.mean += e / static_cast<double>(fast.size());
    a.worst = std::max(a.worst, e);
  }
  return a;
}

// Two images compared as the glossy acceptance asks: the luminance of each block × block square of
// pixels, relative to the second image's.
struct BlockAgreement {
  int blocks = 0;
  double mean = 0, worst = 0;  // relative differences of block luminance
  bool finite = true;          // every block finite, the second image's positive
};

inline BlockAgreement compare_blocks(const Image& a, const Image& b, int block) {
  BlockAgreement out;
  double sum = 0;
  for (int by = 0; by < std::min(a.height, b.height) / block; ++by) {
    for (int bx = 0; bx < std::min(a.width, b.width) / block; ++bx) {
      double la = 0, lb = 0;
      for (int y = by * block; y < (by + 1) * block; ++y) {
        for (int x = bx * block; x < (bx + 1) * block; ++x) {
          la += luminance(a.at(x, y));
          lb += luminance(b.at(x, y));
        }
      }
      if (!(std::isfinite(la) && std::isfinite(lb) && lb > 0)) {
        out.finite = false;
        continue;
      }
      const double e = std::abs(la - lb) / lb;
      sum += e;
      out.worst = std::max(out.worst, e);
      ++out.blocks;
    }
  }
  out.mean = out.blocks > 0 ? sum / out.blocks : 1.0;
  return out;
}

}  // namespace relight::testing
