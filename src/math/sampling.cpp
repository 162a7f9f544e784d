#include "math/sampling.h"

#include <algorithm>
#include <cmath>

namespace relight {

Pcg32::Pcg32(std::uint64_t seed, std::uint64_t stream) : increment_((stream << 1u) | 1u) {
  next_u32();
  state_ += seed;
  next_u32();
}

std::uint32_t Pcg32::next_u32() {
  const std::uint64_t old = state_;
  state_ = old * 6364136223846793005ULL + increment_;
  const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
  const auto rot = static_cast<std::uint32_t>(old >> 59u);
  return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

double Pcg32::next_double() { return next_u32() * (1.0 / 4294967296.0); }

Vec3 sample_cosine_hemisphere(double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

Vec3 sample_uniform_sphere(double u1, double u2) {
  const double z = 1.0 - 2.0 * u1;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace relight
