// The SH addition theorem Σ_m Y_lm(a) Y_lm(b) = (2l+1)/4π P_l(a·b) (Dobashi et al. 1995
// Eq. 7), which the zonal aiming of luminaires relies on, for every band l < 32.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/legendre.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/test_util.h"

namespace relight {
namespace {

TEST(ShAdditionTheorem, HoldsForAllBandsBelow32To1e9) {
  const int order = 32;
  Pcg32 rng(11, 12);
  std::vector<double> ya(sh_count(order)), yb(sh_count(order));
  double worst = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = test::random_direction(rng);
    // Include near-parallel and antiparallel pairs besides random ones.
    Vec3 b = test::random_direction(rng);
    if (trial % 10 == 1) b = normalize(a + b * 1e-3);
    if (trial % 10 == 2) b = -a;
    sh_eval(order, a, ya);
    sh_eval(order, b, yb);
    for (int l = 0; l < order; ++l) {
      double sum = 0.0;
      for (int m = -l; m <= l; ++m) sum += ya[sh_index(l, m)] * yb[sh_index(l, m)];
      const double expected = (2 * l + 1) / (4 * kPi) * legendre(l, dot(a, b));
      worst = std::max(worst, std::abs(sum - expected));
    }
  }
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace relight
