// SH rotation by the Ivanic–Ruedenberg recursion (math/sh_rotation.h): rotating coefficients
// must equal projecting the rotated function, for random rotations and generic functions.
#include "math/sh_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/frame.h"
#include "math/sampling.h"
#include "math/sh.h"
#include "math/test_util.h"
#include "math/zonal.h"

namespace relight {
namespace {

std::vector<double> rotate(const ShRotation& rot, const std::vector<double>& c) {
  std::vector<double> out(c.size());
  sh_rotate(rot, c, out);
  return out;
}

// Projection of g(d) = f(Rᵀ d), f given by its coefficients (exact quadrature).
std::vector<double> project_rotated(const std::vector<double>& c, const Mat3& r) {
  const int order = sh_order_from_count(c.size());
  const Mat3 rt = transpose(r);
  return sh_project(order, [&](Vec3 d) { return sh_evaluate(c, rt * d); });
}

TEST(ShRotation, RotatingCoefficientsEqualsProjectingRotatedFunctionUpToOrder16By1e5) {
  Pcg32 rng(21, 22);
  double worst = 0.0;
  for (int order = 1; order <= 16; ++order) {
    for (int trial = 0; trial < 4; ++trial) {
      const Mat3 r = test::random_rotation(rng);
      const std::vector<double> c = test::random_coefficients(rng, order);
      const double err =
          test::max_abs_diff(rotate(make_sh_rotation(order, r), c), project_rotated(c, r));
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-5) << "order " << order << " trial " << trial;
    }
  }
  EXPECT_LT(worst, 1e-11);  // in fact to rounding
}

TEST(ShRotation, StableAtOrder32By1e9) {
  Pcg32 rng(23, 24);
  const int order = 32;
  for (int trial = 0; trial < 2; ++trial) {
    const Mat3 r = test::random_rotation(rng);
    const ShRotation rot = make_sh_rotation(order, r);
    // Every band matrix stays orthogonal.
    for (int l = 0; l < order; ++l) {
      double worst = 0.0;
      for (int a = -l; a <= l; ++a)
        for (int b = -l; b <= l; ++b) {
          double s = 0.0;
          for (int k = -l; k <= l; ++k) s += rot.element(l, a, k) * rot.element(l, b, k);
          worst = std::max(worst, std::abs(s - (a == b ? 1.0 : 0.0)));
        }
      EXPECT_LT(worst, 1e-10) << "band " << l;
    }
    const std::vector<double> c = test::random_coefficients(rng, order);
    EXPECT_LT(test::max_abs_diff(rotate(rot, c), project_rotated(c, r)), 1e-9);
  }
}

TEST(ShRotation, IdentityAndCompositionTo1e12) {
  Pcg32 rng(25, 26);
  const int order = 12;
  const std::vector<double> c = test::random_coefficients(rng, order);
  EXPECT_LT(test::max_abs_diff(rotate(make_sh_rotation(order, mat3_identity()), c), c), 1e-15);
  const Mat3 r1 = test::random_rotation(rng), r2 = test::random_rotation(rng);
  const std::vector<double> two_steps =
      rotate(make_sh_rotation(order, r1), rotate(make_sh_rotation(order, r2), c));
  EXPECT_LT(test::max_abs_diff(rotate(make_sh_rotation(order, r1 * r2), c), two_steps), 1e-12);
  // The inverse rotation undoes it.
  EXPECT_LT(test::max_abs_diff(rotate(make_sh_rotation(order, transpose(r1)),
                                      rotate(make_sh_rotation(order, r1), c)),
                               c),
            1e-12);
}

TEST(ShRotation, AboutZAxisMixesCosineAndSinePairsTo1e13) {
  Pcg32 rng(27, 28);
  const int order = 10;
  const double alpha = 0.7;
  const std::vector<double> c = test::random_coefficients(rng, order);
  const std::vector<double> out =
      rotate(make_sh_rotation(order, mat3_rotation({0, 0, 1}, alpha)), c);
  for (int l = 0; l < order; ++l) {
    EXPECT_NEAR(out[sh_index(l, 0)], c[sh_index(l, 0)], 1e-13);
    for (int m = 1; m <= l; ++m) {
      const double cm = c[sh_index(l, m)], sm = c[sh_index(l, -m)];
      EXPECT_NEAR(out[sh_index(l, m)], std::cos(m * alpha) * cm - std::sin(m * alpha) * sm, 1e-13);
      EXPECT_NEAR(out[sh_index(l, -m)], std::sin(m * alpha) * cm + std::cos(m * alpha) * sm, 1e-13);
    }
  }
}

TEST(ShRotation, FrameMapsLocalLobeToWorldAxisTo1e12) {
  // A zonal lobe about local +z, rotated by the frame, is the same lobe about frame.n.
  Pcg32 rng(29, 30);
  const int order = 16;
  std::vector<double> zonal(order);
  for (double& z : zonal) z = 2 * rng.next_double() - 1;
  std::vector<double> local(sh_count(order), 0.0);
  for (int l = 0; l < order; ++l) local[sh_index(l, 0)] = zonal[l];
  for (int trial = 0; trial < 5; ++trial) {
    const Vec3 n = test::random_direction(rng);
    const Frame f = frame_from_normal(n);
    const std::vector<double> world = rotate(make_sh_rotation(order, f), local);
    EXPECT_LT(test::max_abs_diff(world, zonal_rotate(zonal, n)), 1e-12);
    // Same as building from the explicit matrix.
    EXPECT_EQ(world, rotate(make_sh_rotation(order, mat3_from_frame(f)), local));
  }
}

TEST(ShRotation, RgbBatchAndLowerOrderAgreeWithScalarTo1e15) {
  Pcg32 rng(31, 32);
  const int order = 8;
  const ShRotation rot = make_sh_rotation(order, test::random_rotation(rng));
  const std::vector<double> a = test::random_coefficients(rng, order);
  const std::vector<double> b = test::random_coefficients(rng, order);
  std::vector<Rgb> rgb(a.size()), rgb_out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) rgb[i] = {a[i], b[i], a[i] - b[i]};
  sh_rotate(rot, rgb, rgb_out);
  const std::vector<double> ra = rotate(rot, a), rb = rotate(rot, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(rgb_out[i].r, ra[i], 1e-15);
    EXPECT_NEAR(rgb_out[i].g, rb[i], 1e-15);
    EXPECT_NEAR(rgb_out[i].b, ra[i] - rb[i], 1e-14);
  }
  std::vector<double> ab(a);
  ab.insert(ab.end(), b.begin(), b.end());
  std::vector<double> ab_out(ab.size());
  sh_rotate_batch(rot, ab, ab_out);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(ab_out[i], ra[i]);
    EXPECT_EQ(ab_out[a.size() + i], rb[i]);
  }
  // A rotation built for 8 bands rotates a 5-band vector as a 5-band rotation would.
  const std::vector<double> low(a.begin(), a.begin() + 25);
  std::vector<double> low_out(25);
  sh_rotate(rot, low, low_out);
  for (int i = 0; i < 25; ++i) EXPECT_EQ(low_out[i], ra[i]);
}

}  // namespace
}  // namespace relight
