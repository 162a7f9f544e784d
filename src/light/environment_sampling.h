// Directions drawn in proportion to an environment's continuous radiance (for the reference's
// next-event estimate of a top-level environment, reference/reference_tracer.cpp). A
// piecewise-constant density over an equirectangular grid (math/equirect.h): for a map the map's
// own texels weighted by their luminance and solid angle, so that a small bright source in the map
// is drawn exactly where it is (the map is looked up per texel); for a sky or a uniform environment
// a 256 × 128 grid of the continuous part's luminance at texel centres, with a floor of 1 % of the
// mean so that no direction of light has density zero. A texel is drawn from the cumulative sums
// (rows, then columns), the direction uniformly within it (φ and cos θ, so uniform per steradian).
// The sun disc of a sky is not in it (the tracer samples the disc's cone). Unbiased with any grid:
// the estimator divides by the density it drew with. Pinned by
// tests/light/environment_sampling_test.cpp.
#pragma once

#include <vector>

#include "light/environment.h"
#include "math/vec3.h"

namespace relight {

class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const Environment& env);

  struct Sample {
    Vec3 direction;  // unit, world frame
    double pdf = 0;  // per steradian; 0 when the environment is black
  };
  // The direction for two uniform numbers in [0, 1).
  Sample sample(double u1, double u2) const;
  // The density of drawing unit world direction `dir`.
  double pdf(Vec3 dir) const;
  bool empty() const { return total_ <= 0; }

 private:
  int width_ = 0, height_ = 0;
  MapRotation rotation_{0};
  std::vector<double> row_cdf_;    // height_ + 1, from 0 to 1
  std::vector<double> texel_cdf_;  // per row, width_ + 1 values from 0 to 1
  std::vector<double> weight_;     // per texel: its share of the total
  double total_ = 0;
};

}  // namespace relight
