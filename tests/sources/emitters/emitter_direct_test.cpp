// sources/emitters/emitter_direct.h — the exact direct light of emitters at a point:
//  * a square parallel to the receiver, seen from below its centre: Lambert's closed form for
//    a rectangle (sum of four corner form factors), to 1e-9;
//  * a tilted receiver, the square partly below its horizon: a 600 × 600 midpoint quadrature of
//    L cosθ cosθ' / d² over the visible part, to 1e-3;
//  * behind the emitting side: nothing; a blocker over half the square: about half.
#include <cmath>

#include <gtest/gtest.h>

#include "math/vec3.h"
#include "scene/primitives.h"
#include "sources/emitters/emitter_direct.h"

namespace relight {
namespace {

// Form factor from a point to a parallel rectangle a × b at height c whose corner is straight
// above the point (the classic closed form).
double corner_form_factor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
         (2 * kPi);
}

// A downward-facing square of side `side` centred at `centre`, lit at `luminance`.
PlacedEmitters square(Vec3 centre, double side, double luminance) {
  Emitter e;
  e.name = "panel";
  const Vec3 corner = centre - Vec3{side / 2, 0, side / 2};
  e.geometry = make_quad(corner, {side, 0, 0}, {0, 0, side}, 0);
  e.luminance = luminance;
  e.pivot = centre;
  EmitterState s;
  s.luminance = luminance;
  return place_emitters({e}, {s});
}

TEST(EmitterDirect, ParallelSquareFromBelowItsCentreIsTheRectangleClosedForm) {
  const double side = 0.4, height = 0.35, l = 5000;
  const PlacedEmitters e = square({0, height, 0}, side, l);
  ASSERT_LT(e.normals.at(0).y, -0.99);
  const Rgb got = emitter_direct_irradiance(e, nullptr, {0, 0, 0}, {0, 1, 0});
  const double expected = kPi * l * 4 * corner_form_factor(side / 2, side / 2, height);
  EXPECT_NEAR(got.g / expected, 1, 1e-9);
  // Off-centre, below a corner: one corner form factor of the whole square.
  const Rgb corner = emitter_direct_irradiance(e, nullptr, {-side / 2, 0, -side / 2}, {0, 1, 0});
  EXPECT_NEAR(corner.g / (kPi * l * corner_form_factor(side, side, height)), 1, 1e-9);
}

TEST(EmitterDirect, ATiltedReceiverSeesOnlyWhatIsAboveItsHorizon) {
  const double side = 0.4, height = 0.3, l = 1000;
  const PlacedEmitters e = square({0, height, 0}, side, l);
  const Vec3 n = normalize(Vec3{std::sin(radians(70)), std::cos(radians(70)), 0});
  const Rgb got = emitter_direct_irradiance(e, nullptr, {0.1, 0, 0}, n);
  const int m = 600;
  double sum = 0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const Vec3 y{-side / 2 + side * (i + 0.5) / m, height, -side / 2 + side * (j + 0.5) / m};
      const Vec3 d = y - Vec3{0.1, 0, 0};
      const double r2 = dot(d, d), r = std::sqrt(r2);
      const double cos_r = dot(n, d) / r, cos_e = d.y / r;
      if (cos_r > 0) sum += l * cos_r * cos_e / r2 * (side * side) / (m * m);
    }
  }
  EXPECT_GT(sum, 0);
  EXPECT_NEAR(got.g / sum, 1, 1e-3);
}

TEST(EmitterDirect, BehindTheEmittingSideIsDark) {
  const PlacedEmitters e = square({0, 1, 0}, 0.4, 1000);
  EXPECT_EQ(max_component(emitter_direct_irradiance(e, nullptr, {0, 2, 0}, {0, -1, 0})), 0);
}

TEST(EmitterDirect, ABlockerOverHalfTheSquareHalvesTheLight) {
  const PlacedEmitters e = square({0, 1, 0}, 0.4, 1000);
  // A large opaque quad at half height covering x < 0 (both sides occlude).
  const TriangleSoup blocker = make_quad({-5, 0.5, -5}, {5, 0, 0}, {0, 0, 10}, 0);
  const RayTracer tracer(blocker.positions, blocker.triangles,
                         sequential_ids(blocker.triangles.size()));
  const Occluders occluders(tracer);
  const Rgb open = emitter_direct_irradiance(e, nullptr, {0, 0, 0}, {0, 1, 0}, 64);
  const Rgb half = emitter_direct_irradiance(e, &occluders, {0, 0, 0}, {0, 1, 0}, 64);
  EXPECT_NEAR(half.g / open.g, 0.5, 0.05);
}

}  // namespace
}  // namespace relight
