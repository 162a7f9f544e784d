#include "sources/luminaires/sh_direct.h"

#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/sh.h"

namespace relight {

Eigen::MatrixXf sh_basis_direct(const DirectGeometry& g, int sh_order) {
  const auto n = static_cast<Eigen::Index>(g.factor.size());
  const int k = sh_count(sh_order);
  Eigen::MatrixXf out = Eigen::MatrixXf::Zero(n, k);
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, n), [&](const auto& range) {
    std::vector<double> y(static_cast<std::size_t>(k));
    for (Eigen::Index r = range.begin(); r != range.end(); ++r) {
      const float f = g.factor[static_cast<std::size_t>(r)];
      if (f == 0) continue;
      const auto i = static_cast<std::size_t>(r);
      sh_eval(sh_order, Vec3{g.dir_x[i], g.dir_y[i], g.dir_z[i]}, y);
      for (int b = 0; b < k; ++b)
        out(r, b) = static_cast<float>(y[static_cast<std::size_t>(b)] * f);
    }
  });
  return out;
}

}  // namespace relight
