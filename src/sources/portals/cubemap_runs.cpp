// The encoder of pulse-run records (cubemap_encoding.h): the runs of a receiver's kept cells, then
// the record. Their reading and sums are cubemap_runs_sum.h's.
#include "sources/portals/cubemap_runs.h"

#include "sources/portals/cubemap_encoding.h"

namespace relight::cubemap_detail {

std::size_t find_runs(int n, std::span<const double> cells, const Quantiser& quantise,
                      std::vector<std::uint32_t>& runs) {
  const std::size_t join = 2 * cubemap_code_index_bytes(n);
  runs.clear();
  std::size_t levels = 0;
  for_each_kept(cells, quantise, [&](std::size_t k, long) {
    const auto cell = static_cast<std::uint32_t>(k);
    if (!runs.empty() && k - runs.back() <= join) {
      levels += k + 1 - runs.back();
      runs.back() = cell + 1;
      return;
    }
    runs.push_back(cell);
    runs.push_back(cell + 1);
    ++levels;
  });
  return levels;
}

void write_runs_record(int n, const Quantiser& quantise, std::span<const double> cells,
                       std::span<const std::uint32_t> runs, std::size_t levels,
                       std::vector<std::uint8_t>& out) {
  const std::size_t w = cubemap_code_index_bytes(n);
  out.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kRuns));
  put_float(out, static_cast<float>(quantise.scale));
  put_uint(out, static_cast<std::uint32_t>(runs.size() / 2), w);
  put_uint(out, static_cast<std::uint32_t>(levels), w);
  for (std::size_t j = 0; j < runs.size(); j += 2) {
    put_uint(out, runs[j], w);
    put_uint(out, runs[j + 1] - runs[j], w);
  }
  for (std::size_t j = 0; j < runs.size(); j += 2)
    for (std::uint32_t k = runs[j]; k < runs[j + 1]; ++k)
      out.push_back(static_cast<std::uint8_t>(quantise(k, cells[k])));
}

}  // namespace relight::cubemap_detail
