// The writer of pulse and Haar records (cubemap_encoding.h), which share one layout: the scale
// (Haar: two), the count, the kept entries' indices, then their levels. Their reading and sums
// are cubemap_pulse_sum.h's.
#include "sources/portals/cubemap_pulse.h"

namespace relight::cubemap_detail {

void write_record(int n, CubemapCodeKind kind, const Quantiser& quantise,
                  std::span<const double> values, std::size_t count,
                  std::vector<std::uint8_t>& out) {
  const std::size_t w = cubemap_code_index_bytes(n);
  out.push_back(static_cast<std::uint8_t>(kind));
  put_float(out, static_cast<float>(quantise.scale));
  if (kind == CubemapCodeKind::kHaar) put_float(out, static_cast<float>(quantise.detail_scale));
  put_uint(out, static_cast<std::uint32_t>(count), w);
  for_each_kept(values, quantise,
                [&](std::size_t k, long) { put_uint(out, static_cast<std::uint32_t>(k), w); });
  for_each_kept(values, quantise, [&](std::size_t, long q) {
    out.push_back(static_cast<std::uint8_t>(q & 0xff));  // uint8, or int8 two's complement
  });
}

}  // namespace relight::cubemap_detail
