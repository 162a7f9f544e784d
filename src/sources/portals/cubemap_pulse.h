// The writer of pulse records (cubemap_encoding.h: the kept cells' indices, then their uint8
// levels) and of the Haar records that share their layout, defined in cubemap_pulse.cpp. Their
// reading and sums are cubemap_pulse_sum.h's. Internal to src/sources/portals/cubemap_*.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_encoding.h"

namespace relight::cubemap_detail {

// Appends a pulse or Haar record (`kind`) of the `count` values that `quantise` keeps.
void write_record(int n, CubemapCodeKind kind, const Quantiser& quantise,
                  std::span<const double> values, std::size_t count,
                  std::vector<std::uint8_t>& out);

}  // namespace relight::cubemap_detail
