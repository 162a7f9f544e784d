// engine/runtime_scene.h: the mean of an irradiance field over each vertex's hat function,
// Ē_v = ∫ E φ_v dA / ∫ φ_v dA, by s² sub-triangle centroids a triangle — against closed forms
// on a unit square of two triangles.
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/runtime_scene.h"

namespace relight {
namespace {

struct Square {
  std::vector<Vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<Triangle> triangles{{0, 1, 2}, {0, 2, 3}};
  RuntimeSceneView view() const {
    RuntimeSceneView v;
    v.vertex_count = 4;
    v.receiver_positions = positions;
    v.receiver_normals.assign(4, Vec3{0, 0, 1});
    v.mesh_positions = positions;
    v.opaque_triangles = triangles;
    v.opaque_ids = {0, 1};
    v.vertex_albedo.assign(12, 0.5f);
    return v;
  }
};

std::vector<float> means(const RuntimeScene& scene, const IrradianceField& field, int s) {
  std::vector<float> out(3 * scene.receivers());
  scene.hat_means(field, s, out);
  return out;
}

TEST(RuntimeScene, HatMeanOfAConstantFieldIsTheConstant) {
  const Square square;
  const RuntimeScene scene(square.view(), {});
  for (int s : {0, 1, 2, 4}) {
    const std::vector<float> e = means(
        scene,
        [](Vec3, Vec3) {
          return Rgb{3, 2, 1};
        },
        s);
    for (std::size_t v = 0; v < 4; ++v) {
      EXPECT_NEAR(e[3 * v], 3, 1e-6) << v;
      EXPECT_NEAR(e[3 * v + 2], 1, 1e-6) << v;
    }
  }
}

// For E = x: ∫_t x φ_v = A_t/12 · (2 x_v + x_a + x_b) (∫ φ_i φ_j = A/12, ∫ φ_i² = A/6), and
// ∫ φ_v = Σ A_t / 3. The sub-triangle rule integrates the quadratic x·φ_v with error O(1/s²).
TEST(RuntimeScene, HatMeanOfALinearFieldMatchesTheClosedFormToOrderOneOverSSquared) {
  const Square square;
  const RuntimeScene scene(square.view(), {});
  std::array<double, 4> num{}, den{};
  for (const Triangle& t : square.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      num[v] +=
          0.5 / 12 * (2 * square.positions[v].x + square.positions[a].x + square.positions[b].x);
      den[v] += 0.5 / 3;
    }
  }
  // The corners' φ-weighted centroids (s = 0) are exact for a linear field.
  const std::vector<float> centroids = means(
      scene,
      [](Vec3 p, Vec3) {
        return Rgb{p.x, p.x, p.x};
      },
      0);
  for (std::size_t v = 0; v < 4; ++v) EXPECT_NEAR(centroids[3 * v], num[v] / den[v], 1e-6) << v;
  for (const int s : {4, 16}) {
    const std::vector<float> e = means(
        scene,
        [](Vec3 p, Vec3) {
          return Rgb{p.x, p.x, p.x};
        },
        s);
    double worst = 0;
    for (std::size_t v = 0; v < 4; ++v)
      worst = std::max(worst, std::abs(e[3 * v] - num[v] / den[v]));
    std::printf("s = %d: worst |Ē_v − closed form| %.2e\n", s, worst);
    EXPECT_LT(worst, 0.5 / (s * s)) << s;
  }
}

// What the vertices carry, Σ_v Ē_v ∫φ_v, is the quadrature of ∫ E: for a sun patch's step edge
// (E = 1 for x < 0.3) within one sub-triangle row of the step's length.
TEST(RuntimeScene, HatMeansCarryTheFluxOfASharpEdge) {
  const Square square;
  const RuntimeScene scene(square.view(), {});
  const std::vector<float> e = means(
      scene,
      [](Vec3 p, Vec3) {
        return p.x < 0.3 ? Rgb{1, 1, 1} : Rgb{};
      },
      4);
  // ∫ φ_v: corners 0 and 2 touch both triangles (1/3), corners 1 and 3 one (1/6).
  const double hat[] = {1.0 / 3, 1.0 / 6, 1.0 / 3, 1.0 / 6};
  double flux = 0;
  for (std::size_t v = 0; v < 4; ++v) flux += e[3 * v] * hat[v];
  std::printf("flux of the step carried by the vertices %.4f (exact 0.3)\n", flux);
  EXPECT_NEAR(flux, 0.3, 0.25 / 4);
}

TEST(RuntimeScene, BounceNeedsAStoredGatherOperator) {
  const Square square;
  const RuntimeScene scene(square.view(), {});
  EXPECT_FALSE(scene.can_bounce());
  std::vector<float> direct(12, 1.0f), indirect(12);
  EXPECT_THROW(scene.bounce(direct, indirect, false), std::invalid_argument);
}

}  // namespace
}  // namespace relight
