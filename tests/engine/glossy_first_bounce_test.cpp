// GlossyFirstBounce (engine/glossy_first_bounce.h) on a hand-made operator: two receivers
// gather from a glossy vertex and a Lambertian one; the correction before bouncing is
// Σ_glossy G_rj (π f(l_j, ω_jr) D_j − ρh_j D'_j) exactly (to float precision; D' = D unless
// given), nothing from the
// Lambertian vertex, and with bounces the response is that correction plus its diffuse
// interreflection (two vertices reflecting into each other: a geometric series by hand).
#include <cmath>

#include <gtest/gtest.h>

#include "engine/glossy_first_bounce.h"

namespace relight {
namespace {

TEST(GlossyFirstBounce, CorrectionIsPiFMinusRhoTimesDirectOverGlossyEntries) {
  // Vertices 0 (glossy floor point) and 1 (Lambertian wall point); receivers 0, 1 and a
  // sensor 2 above the floor.
  const std::vector<Vec3> positions{{0, 0, 0}, {2, 1, 0}, {0.5, 2.5, 0.2}};
  const std::vector<Vec3> normals{{0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  GatherOperator g;
  g.matrix.resize(3, 2);
  std::vector<Eigen::Triplet<float>> entries{
      {0, 1, 0.2f}, {1, 0, 0.3f}, {2, 0, 0.25f}, {2, 1, 0.1f}};
  g.matrix.setFromTriplets(entries.begin(), entries.end());
  g.matrix.makeCompressed();
  const MetallicRoughness metal{{0.9, 0.8, 0.7}, 1, 0.3};
  const Rgb rho_h = hemispherical_albedo(metal);
  const std::vector<float> albedo{static_cast<float>(rho_h.r),
                                  static_cast<float>(rho_h.g),
                                  static_cast<float>(rho_h.b),
                                  0.5f,
                                  0.5f,
                                  0.5f};
  BounceSettings settings;
  settings.max_bounces = 0;  // the correction alone
  const GlossyFirstBounce once(g, positions, normals, {0, -1}, {metal}, albedo, settings);
  ASSERT_FALSE(once.empty());

  // A point light at (−1, 3, 0): directions from it to every receiver, and D.
  const Vec3 light{-1, 3, 0};
  std::vector<float> dx, dy, dz, direct{120.0f, 40.0f, 0.0f};
  for (const Vec3& p : positions) {
    const Vec3 d = normalize(p - light);
    dx.push_back(static_cast<float>(d.x));
    dy.push_back(static_cast<float>(d.y));
    dz.push_back(static_cast<float>(d.z));
  }
  std::vector<float> response(9);
  once.respond(dx, dy, dz, direct, response);
  const Vec3 l = normalize(light - positions[0]);
  for (const std::size_t r : {std::size_t{1}, std::size_t{2}}) {
    const float weight = r == 1 ? 0.3f : 0.25f;
    const Rgb f =
        metallic_roughness_brdf(metal, normals[0], l, normalize(positions[r] - positions[0]));
    const Rgb expected = (f * kPi - rho_h) * (weight * 120.0);
    EXPECT_NEAR(response[3 * r], expected.r, 1e-4 * std::abs(expected.r) + 1e-6) << r;
    EXPECT_NEAR(response[3 * r + 1], expected.g, 1e-4 * std::abs(expected.g) + 1e-6) << r;
    EXPECT_NEAR(response[3 * r + 2], expected.b, 1e-4 * std::abs(expected.b) + 1e-6) << r;
  }
  // Receiver 0 gathers only from the Lambertian vertex: no correction.
  for (int c = 0; c < 3; ++c) EXPECT_EQ(response[c], 0.0f);

  // With D' (what the diffuse transfer reflected: a luminaire's SH series) the diffuse part
  // taken out is ρh D', not ρh D.
  const std::vector<float> reflected{60.0f, 20.0f, 0.0f};
  std::vector<float> consistent(9);
  once.respond(dx, dy, dz, direct, consistent, nullptr, reflected);
  for (const std::size_t r : {std::size_t{1}, std::size_t{2}}) {
    const float weight = r == 1 ? 0.3f : 0.25f;
    const Rgb f =
        metallic_roughness_brdf(metal, normals[0], l, normalize(positions[r] - positions[0]));
    const Rgb expected = (f * (kPi * 120.0) - rho_h * 60.0) * weight;
    EXPECT_NEAR(consistent[3 * r], expected.r, 1e-4 * std::abs(expected.r) + 1e-6) << r;
    EXPECT_NEAR(consistent[3 * r + 2], expected.b, 1e-4 * std::abs(expected.b) + 1e-6) << r;
  }

  // With bounces: the correction reflected by the wall (vertex 1, albedo 0.5) reaches row 0.
  BounceSettings bouncing;
  bouncing.tolerance = 1e-9;
  const GlossyFirstBounce full(g, positions, normals, {0, -1}, {metal}, albedo, bouncing);
  std::vector<float> bounced(9);
  full.respond(dx, dy, dz, direct, bounced);
  // Vertex 0 gathers X_0 = 0.2 · 0.5 · (c_1 + X_1) from the wall, which gathers X_1 = 0.3 ρh_c
  // X_0 back from the floor: X_0 = 0.1 c_1 / (1 − 0.03 ρh_c).
  const double rho[3] = {rho_h.r, rho_h.g, rho_h.b};
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.1 * response[3 + c] / (1 - 0.03 * rho[c]);
    EXPECT_NEAR(bounced[c], expected, 1e-5 * std::abs(expected)) << c;
  }
}

}  // namespace
}  // namespace relight
