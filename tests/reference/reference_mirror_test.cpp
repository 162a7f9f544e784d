// reference/reference_mirror.h: the lobe about a light's image that the reference tracer samples
// at Lambertian points. Its density must be the sampler's (else the multiple-importance
// estimate is biased): the mean of 1{ω in a cone}/q(ω) over its samples equals the cone's
// solid angle, 2π (1 − cos θ0), within 1 % for cones inside, across and outside its width;
// and it is none when the point or the light is behind the plane.
#include <cmath>

#include <gtest/gtest.h>

#include "math/sampling.h"
#include "reference/reference_mirror.h"

namespace relight {
namespace {

TEST(ReferenceMirror, TheDensityIsTheSamplers) {
  MirrorPlane floor;
  floor.normal = {0, 1, 0};
  const Vec3 x{1, 2.8, 1}, light{2, 2.5, 2.5};
  const std::optional<MirrorLobe> lobe = mirror_lobe(floor, 0.04, x, light);
  ASSERT_TRUE(lobe.has_value());
  // Its axis points at the image.
  const Vec3 toward = normalize(Vec3{2, -2.5, 2.5} - x);
  EXPECT_NEAR(dot(lobe->axis, toward), 1, 1e-12);
  // β = 2 α s_light / (s_x + s_light): the heights split the path 2.8 : 2.5.
  EXPECT_NEAR(lobe->width, 2 * 0.04 * 2.5 / 5.3, 1e-12);
  Pcg32 rng(5, 1);
  constexpr int kSamples = 400000;
  for (const double cone : {0.5 * lobe->width, 2 * lobe->width, 6 * lobe->width}) {
    double sum = 0;
    for (int i = 0; i < kSamples; ++i) {
      const double u1 = rng.next_double(), u2 = rng.next_double();
      const Vec3 w = sample_mirror_lobe(*lobe, u1, u2);
      if (std::acos(std::min(1.0, dot(w, lobe->axis))) < cone) sum += 1 / mirror_lobe_pdf(*lobe, w);
    }
    const double solid_angle = 2 * kPi * (1 - std::cos(cone));
    EXPECT_NEAR(sum / kSamples, solid_angle, 0.01 * solid_angle) << cone;
  }
}

TEST(ReferenceMirror, NoLobeWhenThePointOrTheLightIsBehindThePlane) {
  MirrorPlane floor;
  floor.normal = {0, 1, 0};
  EXPECT_FALSE(mirror_lobe(floor, 0.01, {1, -0.5, 1}, {2, 2, 2}).has_value());
  EXPECT_FALSE(mirror_lobe(floor, 0.01, {1, 0.5, 1}, {2, -2, 2}).has_value());
  EXPECT_FALSE(mirror_lobe(floor, 0.01, {1, 0, 1}, {2, 2, 2}).has_value());
}

}  // namespace
}  // namespace relight
