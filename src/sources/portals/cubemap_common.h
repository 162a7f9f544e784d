// The pieces that the encoders of the four cubemap records (cubemap_encoding.h) share, internal
// to src/sources/portals/cubemap_*: the quantisation levels (which the readers use too), the stored
// scale, the 8-bit quantiser and the little-endian byte writers.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

namespace relight::cubemap_detail {

constexpr double kPulseLevels = 255.0;  // uint8 0..255
constexpr double kHaarLevels = 127.0;   // int8 −127..127

// The float nearest above x (x ≥ 0 finite): a stored scale that no value exceeds.
inline float scale_at_least(double x) {
  float f = static_cast<float>(x);
  if (!std::isfinite(f))
    throw std::invalid_argument("cubemap encoding: value beyond the float range");
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// How a record's values are quantised: uint8 against `scale` (pulse S, Haar S₀), or for a Haar
// detail int8 against `detail_scale`.
struct Quantiser {
  double scale = 0;
  double detail_scale = 0;    // Haar only
  std::size_t face_mask = 0;  // Haar: N² − 1 (index in face = k & mask); 0 for pulse
  double threshold = 0;

  bool is_detail(std::size_t k) const { return (k & face_mask) != 0; }
  // The quantised value, 0 when dropped.
  long operator()(std::size_t k, double v) const {
    if (v == 0.0) return 0;
    const bool detail = is_detail(k);
    const double s = detail ? detail_scale : scale;
    if (std::abs(v) < threshold * s) return 0;
    return std::lround(v / s * (detail ? kHaarLevels : kPulseLevels));
  }
};

template <class F>
std::size_t for_each_kept(std::span<const double> values, const Quantiser& quantise, F&& visit) {
  std::size_t m = 0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const long q = quantise(k, values[k]);
    if (q == 0) continue;
    visit(k, q);
    ++m;
  }
  return m;
}

inline void put_uint(std::vector<std::uint8_t>& out, std::uint32_t v, std::size_t width) {
  for (std::size_t b = 0; b < width; ++b) out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
}

inline void put_float(std::vector<std::uint8_t>& out, float f) {
  put_uint(out, std::bit_cast<std::uint32_t>(f), 4);
}

}  // namespace relight::cubemap_detail
