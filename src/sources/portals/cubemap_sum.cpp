// Reading a receiver's portal cubemap records (paper 000 §5, Eq. 7; layout and bounds in
// cubemap_encoding.h): a record's parse, its reference decode, and the run-time sparse dot
// product, a record's dispatch to its kind's sum and the block loop of add_receiver_cubemaps with
// its prefetch. Each kind's reader and sums are in its *_sum.h (cubemap_pulse_sum.h,
// cubemap_runs_sum.h, cubemap_rectangles_sum.h), included here alone, so that the compiler
// inlines them into the per-record loop (with internal linkage: see cubemap_sum_common.h).
#include "sources/portals/cubemap_encoding.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/cpu_features.h"
#include "math/haar.h"
#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_face.h"
#include "sources/portals/cubemap_pulse_sum.h"
#include "sources/portals/cubemap_rectangles_sum.h"
#include "sources/portals/cubemap_runs_sum.h"
#include "sources/portals/cubemap_sum_common.h"

namespace relight {

using cubemap_detail::bad_record;
using cubemap_detail::cell_count;
using cubemap_detail::check_face_size;
using cubemap_detail::entry_value;
using cubemap_detail::EntryValue;
using cubemap_detail::for_each_entry;
using cubemap_detail::for_each_rectangle_cell;
using cubemap_detail::for_each_run_cell;
using cubemap_detail::get_uint;
using cubemap_detail::kPulseLevels;
using cubemap_detail::pulse_dot16_avx2;
using cubemap_detail::read_rectangles_header;
using cubemap_detail::read_runs_header;
using cubemap_detail::rectangles_dot;
using cubemap_detail::rectangles_dot_avx2;
using cubemap_detail::rectangles_sum_avx2;
using cubemap_detail::runs_dot;
using cubemap_detail::runs_sum16_avx2;
using cubemap_detail::sparse_dot;

CubemapRecord parse_cubemap_record(int n, std::span<const std::uint8_t> bytes) {
  check_face_size(n);
  if (bytes.empty()) bad_record("truncated (no kind byte)");
  CubemapRecord rec;
  const std::uint8_t kind = bytes[0];
  if (kind == static_cast<std::uint8_t>(CubemapCodeKind::kEmpty)) return rec;
  if (kind != static_cast<std::uint8_t>(CubemapCodeKind::kPulse) &&
      kind != static_cast<std::uint8_t>(CubemapCodeKind::kHaar) &&
      kind != static_cast<std::uint8_t>(CubemapCodeKind::kRuns) &&
      kind != static_cast<std::uint8_t>(CubemapCodeKind::kRectangles))
    bad_record("unknown kind " + std::to_string(kind));
  rec.kind = static_cast<CubemapCodeKind>(kind);
  const std::size_t w = cubemap_code_index_bytes(n);
  if (rec.kind == CubemapCodeKind::kRuns) {
    if (const char* why = read_runs_header(n, bytes, rec)) bad_record(why);
    return rec;
  }
  if (rec.kind == CubemapCodeKind::kRectangles) {
    if (const char* why = read_rectangles_header(n, bytes, rec)) bad_record(why);
    return rec;
  }
  const std::size_t scales = rec.kind == CubemapCodeKind::kHaar ? 8 : 4;
  if (bytes.size() < 1 + scales + w) bad_record("truncated header");
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) bad_record("scale not positive and finite");
  if (rec.kind == CubemapCodeKind::kHaar) {
    rec.detail_scale = std::bit_cast<float>(get_uint(bytes.data() + 5, 4));
    if (!(rec.detail_scale >= 0.0f && std::isfinite(rec.detail_scale)))
      bad_record("detail scale negative or not finite");
  }
  rec.count = get_uint(bytes.data() + 1 + scales, w);
  if (rec.count == 0 || rec.count > cell_count(n)) bad_record("entry count out of range");
  rec.bytes = cubemap_record_bytes(n, rec.kind, rec.count);
  if (bytes.size() < rec.bytes) bad_record("truncated entries");
  rec.indices = bytes.subspan(1 + scales + w, rec.count * w);
  rec.values = bytes.subspan(1 + scales + w + rec.count * w, rec.count);
  return rec;
}

std::size_t decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes,
                                    std::span<double> cells, std::span<double> scratch) {
  const CubemapRecord rec = parse_cubemap_record(n, bytes);
  if (cells.size() != cell_count(n))
    throw std::invalid_argument("cubemap decoding: output must hold 6·N² cells");
  std::fill(cells.begin(), cells.end(), 0.0);
  if (rec.kind == CubemapCodeKind::kPulse) {
    for_each_entry(rec, n, [&](std::size_t k, double t) { cells[k] = t; });
  } else if (rec.kind == CubemapCodeKind::kRuns) {
    const double step = rec.scale / kPulseLevels;
    for_each_run_cell(rec, n, [&](std::size_t k, std::uint8_t q) { cells[k] = q * step; });
  } else if (rec.kind == CubemapCodeKind::kRectangles) {
    const double step = rec.scale / kPulseLevels;
    for_each_rectangle_cell(rec, n, [&](std::size_t k, std::uint8_t q) { cells[k] = q * step; });
  } else if (rec.kind == CubemapCodeKind::kHaar) {
    const std::size_t nn = std::size_t(n) * n;
    for_each_entry(rec, n, [&](std::size_t k, double a) {
      const std::size_t p = k % nn;
      cells[k] = a * haar2d_support(n, static_cast<int>(p / n), static_cast<int>(p % n));
    });
    haar2d_inverse_faces(cells, n, scratch);
  }
  return rec.bytes;
}

std::vector<double> decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes) {
  check_face_size(n);
  std::vector<double> cells(cell_count(n)), scratch(n);
  decode_receiver_cubemap(n, bytes, cells, scratch);
  return cells;
}

Rgb dot_receiver_cubemap(std::span<const std::uint8_t> bytes, const ShellCubemap& shell) {
  const CubemapRecord rec = parse_cubemap_record(shell.n, bytes);
  if (rec.kind == CubemapCodeKind::kEmpty) return {};
  const EntryValue value = entry_value(rec, shell.n);
  if (rec.kind == CubemapCodeKind::kRuns) {
    const Rgb sum =
        cubemap_code_index_bytes(shell.n) == 2 && has_avx2_fma()
            ? runs_sum16_avx2(rec.indices.data(), rec.runs, rec.values.data(), rec.count, shell)
            : runs_dot(rec, shell);
    return sum * static_cast<double>(static_cast<float>(value.scale));
  }
  if (rec.kind == CubemapCodeKind::kRectangles) {
    const Rgb sum = has_avx2_fma() ? rectangles_dot_avx2(rec, shell) : rectangles_dot(rec, shell);
    return sum * static_cast<double>(static_cast<float>(value.scale));
  }
  const std::vector<ShellTexel>& table =
      rec.kind == CubemapCodeKind::kPulse ? shell.cells_float : shell.haar_float;
  if (rec.kind == CubemapCodeKind::kPulse && cubemap_code_index_bytes(shell.n) == 2 &&
      has_avx2_fma())
    return pulse_dot16_avx2(rec, table, static_cast<float>(value.scale));
  return cubemap_code_index_bytes(shell.n) == 2 ? sparse_dot<2>(rec, table, value)
                                                : sparse_dot<4>(rec, table, value);
}

namespace {

// Prefetches the cache lines of `bytes` that record i of `count` is to ask for: [i·L/count,
// (i + 1)·L/count) of its L lines; `next` is the first line not yet asked for.
void prefetch_share(std::span<const std::byte> bytes, std::size_t i, std::size_t count,
                    std::size_t& next) {
  constexpr std::size_t kLine = 64;
  const std::size_t lines = (bytes.size() + kLine - 1) / kLine;
  for (const std::size_t until = (i + 1) * lines / count; next < until; ++next) {
    __builtin_prefetch(bytes.data() + kLine * next);
  }
}

// Record i of a block: bytes [offsets[i], offsets[i + 1]) of `records`, checked.
std::span<const std::uint8_t> record_of(std::span<const std::uint8_t> records,
                                        std::span<const std::uint64_t> offsets, std::size_t i) {
  if (offsets[i + 1] > records.size() || offsets[i] >= offsets[i + 1])
    bad_record("offsets out of order or beyond the records");
  return records.subspan(offsets[i], offsets[i + 1] - offsets[i]);
}

// add_receiver_cubemaps with AVX2 and FMA and 2-byte indices: run and rectangle records parsed
// and summed here (runs_sum16_avx2 and rectangles_sum_avx2 inlined), the other kinds through
// dot_receiver_cubemap. Through dot_receiver_cubemap, each record's parse and checks in
// parse_cubemap_record take half of the records' sum (measured: docs/decisions.md); the header
// checks here are read_runs_header's and read_rectangles_header's, written once for both and
// always inlined (a call is far slower).
__attribute__((target("avx2,fma"))) void add_records_avx2(
    std::span<const std::uint8_t> records, std::span<const std::uint64_t> offsets,
    const ShellCubemap& shell, std::span<float> red, std::span<float> green, std::span<float> blue,
    std::span<const std::byte> read_next) {
  const std::size_t count = offsets.size() - 1;
  std::size_t prefetched = 0;
  for (std::size_t i = 0; i < count; ++i) {
    prefetch_share(read_next, i, count, prefetched);
    const std::span<const std::uint8_t> record = record_of(records, offsets, i);
    if (record[0] == static_cast<std::uint8_t>(CubemapCodeKind::kEmpty)) continue;
    const bool runs = record[0] == static_cast<std::uint8_t>(CubemapCodeKind::kRuns);
    if (runs || record[0] == static_cast<std::uint8_t>(CubemapCodeKind::kRectangles)) {
      CubemapRecord rec;
      if (const char* why = runs ? read_runs_header(shell.n, record, rec)
                                 : read_rectangles_header(shell.n, record, rec))
        bad_record(why);
      const Rgb e =
          runs ? runs_sum16_avx2(rec.indices.data(), rec.runs, rec.values.data(), rec.count, shell)
               : rectangles_sum_avx2(rec.indices.data(), rec.rectangles, rec.values.data(), shell);
      const float step = static_cast<float>(rec.scale / kPulseLevels);
      red[i] += static_cast<float>(e.r) * step;
      green[i] += static_cast<float>(e.g) * step;
      blue[i] += static_cast<float>(e.b) * step;
      continue;
    }
    const Rgb e = dot_receiver_cubemap(record, shell);
    red[i] += static_cast<float>(e.r);
    green[i] += static_cast<float>(e.g);
    blue[i] += static_cast<float>(e.b);
  }
}

}  // namespace

void add_receiver_cubemaps(std::span<const std::uint8_t> records,
                           std::span<const std::uint64_t> offsets, const ShellCubemap& shell,
                           std::span<float> red, std::span<float> green, std::span<float> blue,
                           std::span<const std::byte> read_next) {
  const std::size_t count = offsets.empty() ? 0 : offsets.size() - 1;
  if (red.size() < count || green.size() < count || blue.size() < count)
    throw std::invalid_argument("add_receiver_cubemaps: a sum for each record");
  if (count > 0 && cubemap_code_index_bytes(shell.n) == 2 && has_avx2_fma())
    return add_records_avx2(records, offsets, shell, red, green, blue, read_next);
  std::size_t prefetched = 0;
  for (std::size_t i = 0; i < count; ++i) {
    prefetch_share(read_next, i, count, prefetched);
    const Rgb e = dot_receiver_cubemap(record_of(records, offsets, i), shell);
    red[i] += static_cast<float>(e.r);
    green[i] += static_cast<float>(e.g);
    blue[i] += static_cast<float>(e.b);
  }
}

}  // namespace relight
