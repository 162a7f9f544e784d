// sources/emitters/nearfield_transfer.h (Sun 2005 §3.2.1): unshadowed, a receiver's transfer
// vector is the SH projection of the clamped cosine about its normal (zonal coefficients √π/2,
// √(π/3), √(5π)/8, 0 for l = 0..3); under a blocker it is zero; and E = t · l gives πL under
// uniform radiance L.
#include <cmath>

#include <gtest/gtest.h>

#include "math/sh.h"
#include "math/zonal.h"
#include "scene/primitives.h"
#include "sources/emitters/nearfield_transfer.h"

namespace relight {
namespace {

RayTracer tracer_of(const TriangleSoup& soup) {
  return RayTracer(soup.positions, soup.triangles, sequential_ids(soup.triangles.size()));
}

TEST(NearfieldTransfer, UnshadowedIsTheClampedCosine) {
  const RayTracer nothing({}, {}, {});
  const std::vector<Vec3> positions{{0, 0, 0}, {1, 2, 3}};
  const std::vector<Vec3> normals{{0, 1, 0}, normalize(Vec3{1, -1, 0.5})};
  NearfieldTransferSettings s;
  s.sqrt_directions = 64;
  const std::vector<float> t = nearfield_transfer(nothing, positions, normals, s);
  ASSERT_EQ(t.size(), 2u * 16u);
  const std::vector<double> zonal{std::sqrt(kPi) / 2, std::sqrt(kPi / 3), std::sqrt(5 * kPi) / 8,
                                  0};
  for (std::size_t r = 0; r < 2; ++r) {
    const std::vector<double> expected = zonal_rotate(zonal, normals[r]);
    for (std::size_t k = 0; k < 16; ++k)
      EXPECT_NEAR(t[r * 16 + k], expected[k], 0.01) << r << " " << k;
    // Uniform radiance L = 1: E = t_0 · √(4π) = π.
    EXPECT_NEAR(t[r * 16] * std::sqrt(4 * kPi), kPi, 2e-3);
  }
}

TEST(NearfieldTransfer, ABlockerAboveShadowsTheReceiver) {
  const RayTracer roof = tracer_of(make_quad({-100, 1, 100}, {200, 0, 0}, {0, 0, -200}, 0));
  const std::vector<Vec3> positions{{0, 0, 0}};
  const std::vector<Vec3> normals{{0, 1, 0}};
  const std::vector<float> t = nearfield_transfer(roof, positions, normals, {});
  // Only directions within atan(1/100) of the horizon pass: E ≤ 1e-3 of the open value.
  EXPECT_LT(std::fabs(t[0]), 1e-3);
}

}  // namespace
}  // namespace relight
