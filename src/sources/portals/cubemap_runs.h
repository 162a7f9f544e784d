// The encoder of pulse-run records (cubemap_encoding.h), in two steps defined in cubemap_runs.cpp.
// Their reading and sums are cubemap_runs_sum.h's. Internal to src/sources/portals/cubemap_*.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sources/portals/cubemap_common.h"

namespace relight::cubemap_detail {

// The runs of the pulse record's kept cells, as [start, end) pairs in `runs`: a gap of at most
// 2W cells joins its two runs (stored as zero levels, never more bytes than a run's start and
// length). Returns the levels the runs hold.
std::size_t find_runs(int n, std::span<const double> cells, const Quantiser& quantise,
                      std::vector<std::uint32_t>& runs);

// Appends the run record of `runs` (find_runs's), which hold `levels` levels.
void write_runs_record(int n, const Quantiser& quantise, std::span<const double> cells,
                       std::span<const std::uint32_t> runs, std::size_t levels,
                       std::vector<std::uint8_t>& out);

}  // namespace relight::cubemap_detail
