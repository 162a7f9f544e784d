// Two images compared as the glossy acceptance asks (issue 13): the luminance of each
// block × block square of pixels, relative to the second image's.
#pragma once

#include <algorithm>
#include <cmath>

#include "image/image.h"

namespace relight::testing {

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
