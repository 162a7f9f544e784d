// The environment sampler (light/environment_sampling.h): the density it reports is the one
// it draws with and integrates to one, and drawing by it integrates a map with a small bright
// source to its closed form from few samples.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "light/environment.h"
#include "light/environment_sampling.h"
#include "math/equirect.h"
#include "math/sampling.h"

namespace relight {
namespace {

// A 512 × 256 map of luminance 100 cd/m² with a 2 × 2-texel source of 10⁶ cd/m² 50° above the
// horizon (about 0.7° across), rotated 30°.
Environment small_source_map(double& source_solid_angle, Vec3& source_direction) {
  auto map = std::make_shared<EquirectMap>();
  map->width = 512;
  map->height = 256;
  map->texels.assign(512 * 256, Rgb{100, 100, 100});
  const int j0 = static_cast<int>(std::round(256 * 40.0 / 180)) - 1, i0 = 100;
  source_solid_angle = 0;
  for (int j = j0; j < j0 + 2; ++j) {
    for (int i = i0; i < i0 + 2; ++i) {
      map->texels[static_cast<std::size_t>(j) * 512 + i] = Rgb{1e6, 1e6, 1e6};
      source_solid_angle += equirect_row_solid_angle(512, 256, j);
    }
  }
  source_direction =
      MapRotation(30).to_world(equirect_direction((i0 + 1.0) / 512, (j0 + 1.0) / 256));
  return make_map_environment(map, 30, 1);
}

TEST(EnvironmentSampling, TheDensityDrawnIsTheDensityReportedAndIntegratesToOne) {
  double omega = 0;
  Vec3 toward;
  const Environment env = small_source_map(omega, toward);
  const EnvironmentSampler sampler(env);
  Pcg32 rng(7, 1);
  double mean_inverse = 0;  // E[1/p] over p-distributed directions = ∫ dω where p > 0 = 4π
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const EnvironmentSampler::Sample s = sampler.sample(rng.next_double(), rng.next_double());
    ASSERT_GT(s.pdf, 0);
    EXPECT_NEAR(length(s.direction), 1, 1e-12);
    EXPECT_NEAR(sampler.pdf(s.direction) / s.pdf, 1, 1e-9);
    mean_inverse += 1 / s.pdf / n;
  }
  EXPECT_NEAR(mean_inverse, 4 * kPi, 0.02 * 4 * kPi);
}

TEST(EnvironmentSampling, AHorizontalPlaneUnderASmallSourceMatchesTheClosedFormFromFewSamples) {
  double omega = 0;
  Vec3 toward;
  const Environment env = small_source_map(omega, toward);
  const EnvironmentSampler sampler(env);
  // E on an upward plane: the uniform part πL plus the source's (L_s − L) Ω cos θ (2 × 2
  // texels, cos θ at their centre; the texels span 1.4°, so that is good to 1e-3).
  const double closed = kPi * 100 + (1e6 - 100) * omega * toward.y;
  Pcg32 rng(11, 2);
  const int n = 4096;
  double e = 0;
  for (int k = 0; k < n; ++k) {
    const EnvironmentSampler::Sample s = sampler.sample(rng.next_double(), rng.next_double());
    if (s.direction.y > 0) e += env.radiance(s.direction).g * s.direction.y / s.pdf / n;
  }
  std::printf("small source: closed form %.1f lx, 4096 samples %.1f lx\n", closed, e);
  EXPECT_NEAR(e, closed, 0.01 * closed);
}

}  // namespace
}  // namespace relight
