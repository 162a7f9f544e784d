// Random numbers and direction sampling for Monte Carlo estimators.
// Pcg32 is O'Neill's PCG-XSH-RR generator (pcg-random.org, 2014): small state,
// independent streams, so every pixel/sensor/sample gets a deterministic sequence
// from (seed, stream) regardless of thread scheduling.
#pragma once

#include <cstdint>

#include "math/vec3.h"

namespace relight {

class Pcg32 {
 public:
  Pcg32(std::uint64_t seed, std::uint64_t stream);
  std::uint32_t next_u32();
  // Uniform in [0, 1).
  double next_double();

 private:
  std::uint64_t state_ = 0;
  std::uint64_t increment_ = 0;
};

// The first two dimensions of the Sobol sequence (van der Corput and Sobol's second
// generator matrix), each scrambled by a random XOR (Kollig & Keller 2002, "Efficient
// multidimensional sampling"): a (0,2)-sequence, so any power-of-two prefix stratifies
// every elementary interval, and the scramble decorrelates neighbouring receivers.
std::uint32_t van_der_corput(std::uint32_t i, std::uint32_t scramble);
std::uint32_t sobol2(std::uint32_t i, std::uint32_t scramble);
// 32 random bits as a number in [0, 1).
constexpr double unit_interval(std::uint32_t bits) {
  return bits * (1.0 / 4294967296.0);
}

// Cosine-weighted direction about +z (pdf = cosθ/π), Malley's method.
Vec3 sample_cosine_hemisphere(double u1, double u2);
// Uniform direction on the unit sphere (pdf = 1/4π).
Vec3 sample_uniform_sphere(double u1, double u2);

}  // namespace relight
