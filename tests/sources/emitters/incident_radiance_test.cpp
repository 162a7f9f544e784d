// sources/emitters/incident_radiance.h (Sun 2005 §3.3.4): a small isotropic (Lambertian) emitter
// far away is a point light — its sampled SH coefficients match the closed form l_k = (I/d²)
// Y_k(ω₀) with I = L·πa² within 1 % — and the harmonic mean distance is its distance; an occluder
// between blocks it entirely.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "math/sh.h"
#include "scene/primitives.h"
#include "sources/emitters/incident_radiance.h"

namespace relight {
namespace {

RayTracer tracer_of(const TriangleSoup& soup) {
  std::vector<std::uint32_t> ids(soup.triangles.size(), 0);  // one emitter: radiance id 0
  return RayTracer(soup.positions, soup.triangles, ids);
}

TEST(IncidentRadiance, SmallFarEmitterIsThePointLightClosedForm) {
  const double a = 0.25, d = 6;
  const Vec3 x{0.3, 1.0, -0.2};
  const Vec3 dir = normalize(Vec3{2, 3, -1});
  const RayTracer sphere = tracer_of(make_sphere(x + d * dir, a, Facing::kOutward, 4, 0));
  const Rgb radiance{1000, 2000, 500};
  IncidentRadianceSettings s;
  s.face_size = 32;
  const IncidentRadiance in =
      sample_incident_radiance(x, sphere, std::span(&radiance, 1), {}, nullptr, s);
  std::vector<double> y(16);
  sh_eval(4, dir, y);
  const double intensity_over_d2 = kPi * a * a / (d * d);  // I/d² per unit radiance
  double error = 0, norm = 0;
  for (std::size_t k = 0; k < 16; ++k) {
    const double expected = radiance.g * intensity_over_d2 * y[k];
    error += (in.sh[k].g - expected) * (in.sh[k].g - expected);
    norm += expected * expected;
    EXPECT_NEAR(in.sh[k].r / in.sh[k].g, 0.5, 1e-12);  // colour kept per channel
  }
  EXPECT_LT(std::sqrt(error / norm), 0.01) << "relative L2 error of the 16 coefficients";
  std::printf(
      "point-light closed form: relative L2 error %.4f, solid angle %.5f sr of %.5f, "
      "harmonic mean distance %.3f m of %.3f\n",
      std::sqrt(error / norm), in.emitter_solid_angle, kPi * a * a / (d * d),
      in.harmonic_mean_distance, d);
  EXPECT_NEAR(in.emitter_solid_angle, kPi * a * a / (d * d), 0.01 * kPi * a * a / (d * d));
  EXPECT_NEAR(in.harmonic_mean_distance, d, 0.05 * d);
}

TEST(IncidentRadiance, OccludedEmitterAddsNothing) {
  const RayTracer sphere = tracer_of(make_sphere({0, 5, 0}, 0.5, Facing::kOutward, 3, 0));
  const TriangleSoup wall = make_quad({-10, 2, 10}, {20, 0, 0}, {0, 0, -20}, 0);
  std::vector<std::uint32_t> ids(wall.triangles.size(), 0);
  const RayTracer blocker(wall.positions, wall.triangles, ids);
  const Rgb radiance{100, 100, 100};
  const IncidentRadiance in =
      sample_incident_radiance({0, 0, 0}, sphere, std::span(&radiance, 1), {}, &blocker, {});
  EXPECT_EQ(sh_luminance_norm(in.sh), 0);
  EXPECT_TRUE(std::isinf(in.harmonic_mean_distance));
}

}  // namespace
}  // namespace relight
