// Pulse / pulse-run / face-rectangle / per-face Haar encoding of a receiver's portal cubemap, 8-bit
// quantised, and the run-time sparse dot product (paper 000 §4.1.2, §5, Eq. 7); layout and bounds
// in cubemap_encoding.h.
#include "sources/portal/cubemap_encoding.h"

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/cpu_features.h"
#include "common/input_error.h"
#include "math/haar.h"

namespace relight {
namespace {

constexpr double kPulseLevels = 255.0;  // uint8 0..255
constexpr double kHaarLevels = 127.0;   // int8 −127..127

void check_face_size(int n) {
  if (!is_power_of_two(n))
    throw std::invalid_argument("cubemap encoding: face size " + std::to_string(n) +
                                " is not a power of two");
}

std::size_t cell_count(int n) {
  return std::size_t{6} * n * n;
}

// The float nearest above x (x ≥ 0 finite): a stored scale that no value exceeds.
float scale_at_least(double x) {
  float f = static_cast<float>(x);
  if (!std::isfinite(f))
    throw std::invalid_argument("cubemap encoding: value beyond the float range");
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// Orthonormal per-face Haar coefficients turned into amplitudes a_k = T_k / S_k (in place).
void to_amplitudes(std::span<double> coefficients, int n) {
  for (std::size_t start = 0; start < coefficients.size(); start += std::size_t(n) * n)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        coefficients[start + std::size_t(r) * n + c] /= haar2d_support(n, r, c);
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

void put_uint(std::vector<std::uint8_t>& out, std::uint32_t v, std::size_t width) {
  for (std::size_t b = 0; b < width; ++b) out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
}

std::uint32_t get_uint(const std::uint8_t* p, std::size_t width) {
  std::uint32_t v = 0;
  for (std::size_t b = 0; b < width; ++b) v |= std::uint32_t{p[b]} << (8 * b);
  return v;
}

void put_float(std::vector<std::uint8_t>& out, float f) {
  put_uint(out, std::bit_cast<std::uint32_t>(f), 4);
}

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

// The runs of the pulse record's kept cells, as [start, end) pairs in `runs`: a gap of at most
// 2W cells joins its two runs (stored as zero levels, never more bytes than a run's start and
// length). Returns the levels the runs hold.
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

using FaceRectangles = std::array<std::array<int, 4>, 6>;

// The bounding rectangle of the pulse record's kept cells on each face, x0, y0, x1, y1
// inclusive (x0 > x1 on a face with none). Returns the levels they hold; `count` the faces
// that have one.
std::size_t find_rectangles(int n, std::span<const double> cells, const Quantiser& quantise,
                            FaceRectangles& rectangles, std::size_t& count) {
  for (std::array<int, 4>& r : rectangles) r = {n, n, -1, -1};
  const std::size_t nn = std::size_t(n) * n;
  for_each_kept(cells, quantise, [&](std::size_t k, long) {
    std::array<int, 4>& r = rectangles[k / nn];
    const auto x = static_cast<int>(k % n), y = static_cast<int>(k % nn / n);
    r = {std::min(r[0], x), std::min(r[1], y), std::max(r[2], x), std::max(r[3], y)};
  });
  std::size_t levels = 0;
  count = 0;
  for (const std::array<int, 4>& r : rectangles) {
    if (r[0] > r[2]) continue;
    levels += static_cast<std::size_t>(r[2] - r[0] + 1) * static_cast<std::size_t>(r[3] - r[1] + 1);
    ++count;
  }
  return levels;
}

void write_rectangles_record(int n, const Quantiser& quantise, std::span<const double> cells,
                             const FaceRectangles& rectangles, std::size_t count,
                             std::vector<std::uint8_t>& out) {
  out.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kRectangles));
  put_float(out, static_cast<float>(quantise.scale));
  out.push_back(static_cast<std::uint8_t>(count));
  for (std::size_t face = 0; face < 6; ++face) {
    const std::array<int, 4>& r = rectangles[face];
    if (r[0] > r[2]) continue;
    for (const int v : {static_cast<int>(face), r[0], r[1], r[2] - r[0], r[3] - r[1]})
      out.push_back(static_cast<std::uint8_t>(v));
  }
  const std::size_t nn = std::size_t(n) * n;
  for (std::size_t face = 0; face < 6; ++face) {
    const std::array<int, 4>& r = rectangles[face];
    for (int y = r[1]; r[0] <= r[2] && y <= r[3]; ++y)
      for (int x = r[0]; x <= r[2]; ++x) {
        const std::size_t k = face * nn + static_cast<std::size_t>(y) * n + x;
        out.push_back(static_cast<std::uint8_t>(quantise(k, cells[k])));
      }
  }
}

[[noreturn]] void bad_record(const std::string& reason) {
  throw InputError("cubemap record: " + reason);
}

// The value of entry byte q: unsigned, or signed for a Haar detail (index in face ≠ 0).
struct EntryValue {
  double scale = 0, detail_scale = 0;
  std::size_t face_mask = 0;
  double operator()(std::size_t k, std::uint8_t q) const {
    return (k & face_mask) != 0 ? static_cast<std::int8_t>(q) * detail_scale : q * scale;
  }
};

EntryValue entry_value(const CubemapRecord& rec, int n) {
  if (rec.kind == CubemapCodeKind::kHaar)
    return {rec.scale / kPulseLevels, rec.detail_scale / kHaarLevels, std::size_t(n) * n - 1};
  return {rec.scale / kPulseLevels, 0.0, 0};
}

// Calls visit(index, value) for each entry, checking indices are increasing and < limit.
template <class F>
void for_each_entry(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t w = cubemap_code_index_bytes(n), limit = cell_count(n);
  const EntryValue value = entry_value(rec, n);
  std::size_t previous = 0;
  for (std::size_t e = 0; e < rec.count; ++e) {
    const std::size_t k = get_uint(rec.indices.data() + e * w, w);
    if (k >= limit || (e > 0 && k <= previous)) bad_record("index out of range or not increasing");
    previous = k;
    visit(k, value(k, rec.values[e]));
  }
}

// Checks a run of a run record: it starts at or after `end` (the previous run's end) and holds
// `length` of the `left` levels not yet taken; `limit` cells in all.
void check_run(std::size_t start, std::size_t length, std::size_t end, std::size_t left,
               std::size_t limit) {
  if (start < end || length == 0 || length > left || start + length > limit)
    bad_record("run out of range, overlapping or beyond the record's levels");
}

// Reads the header of the run record at bytes[0] (kind 3) for face size n into `rec`: nullptr,
// or why it is malformed. The one check of a run header, for parse_cubemap_record and the block
// loop of add_receiver_cubemaps, which inlines it (a call through parse_cubemap_record a record
// was half that loop's time).
[[gnu::always_inline]] inline const char* read_runs_header(int n,
                                                           std::span<const std::uint8_t> bytes,
                                                           CubemapRecord& rec) {
  const std::size_t w = cubemap_code_index_bytes(n);
  if (bytes.size() < 1 + 4 + 2 * w) return "truncated header";
  rec.kind = CubemapCodeKind::kRuns;
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) return "scale not positive and finite";
  rec.runs = get_uint(bytes.data() + 5, w);
  rec.count = get_uint(bytes.data() + 5 + w, w);
  if (rec.count == 0 || rec.count > cell_count(n)) return "level count out of range";
  if (rec.runs == 0 || rec.runs > rec.count) return "run count out of range";
  rec.bytes = cubemap_record_bytes(n, rec.kind, rec.count, rec.runs);
  if (bytes.size() < rec.bytes) return "truncated runs";
  rec.indices = bytes.subspan(5 + 2 * w, 2 * w * rec.runs);
  rec.values = bytes.subspan(5 + 2 * w + 2 * w * rec.runs, rec.count);
  return nullptr;
}

// Calls visit(cell, level) for each cell of a run record, checking its runs.
template <class F>
void for_each_run_cell(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t w = cubemap_code_index_bytes(n), limit = cell_count(n);
  std::size_t end = 0, used = 0;
  for (std::size_t j = 0; j < rec.runs; ++j) {
    const std::size_t start = get_uint(rec.indices.data() + 2 * j * w, w);
    const std::size_t length = get_uint(rec.indices.data() + (2 * j + 1) * w, w);
    check_run(start, length, end, rec.count - used, limit);
    for (std::size_t i = 0; i < length; ++i) visit(start + i, rec.values[used + i]);
    used += length;
    end = start + length;
  }
  if (used != rec.count) bad_record("runs hold fewer cells than the record's levels");
}

// Reads the header of the rectangle record at bytes[0] (kind 4) for face size n into `rec`,
// checking every rectangle (so the sums test nothing): nullptr, or why it is malformed. The
// one check of a rectangle header, for parse_cubemap_record and add_receiver_cubemaps' block
// loop, which inlines it.
[[gnu::always_inline]] inline const char* read_rectangles_header(
    int n, std::span<const std::uint8_t> bytes, CubemapRecord& rec) {
  if (!cubemap_rectangles_fit(n)) return "rectangles for faces of more than 256 cells";
  if (bytes.size() < 6) return "truncated header";
  rec.kind = CubemapCodeKind::kRectangles;
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) return "scale not positive and finite";
  rec.rectangles = bytes[5];
  if (rec.rectangles == 0 || rec.rectangles > 6) return "rectangle count out of range";
  if (bytes.size() < 6 + 5 * rec.rectangles) return "truncated rectangles";
  const std::uint8_t* r = bytes.data() + 6;
  std::size_t levels = 0;
  int previous = -1;
  for (std::size_t j = 0; j < rec.rectangles; ++j, r += 5) {
    const int face = r[0], w = r[3] + 1, h = r[4] + 1;
    if (face <= previous || face > 5 || r[1] + w > n || r[2] + h > n)
      return "rectangle beyond its face or faces out of order";
    previous = face;
    levels += static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  }
  rec.count = levels;
  rec.bytes = cubemap_record_bytes(n, rec.kind, rec.count, rec.rectangles);
  if (bytes.size() < rec.bytes) return "truncated levels";
  rec.indices = bytes.subspan(6, 5 * rec.rectangles);
  rec.values = bytes.subspan(6 + 5 * rec.rectangles, rec.count);
  return nullptr;
}

// Calls visit(cell, level) for each cell of a rectangle record read by read_rectangles_header.
template <class F>
void for_each_rectangle_cell(const CubemapRecord& rec, int n, F&& visit) {
  const std::size_t nn = std::size_t(n) * n;
  const std::uint8_t* level = rec.values.data();
  for (std::size_t j = 0; j < rec.rectangles; ++j) {
    const std::uint8_t* r = rec.indices.data() + 5 * j;
    for (int y = r[2]; y <= r[2] + r[4]; ++y)
      for (int x = r[1]; x <= r[1] + r[3]; ++x)
        visit(r[0] * nn + static_cast<std::size_t>(y) * n + x, *level++);
  }
}

// The hot loop: Σ table[k]·value(k, q) over the entries, in float: a texel is one 4-float
// load, and four accumulators take the entries in turn (one accumulator waited four cycles per
// entry on the previous add). A face average (k & face_mask == 0) is uint8 levels × scale, a
// Haar detail int8 levels × detail scale; a pulse record has no details (face_mask 0).
template <std::size_t W>
Rgb sparse_dot(const CubemapRecord& rec, const std::vector<ShellTexel>& table,
               const EntryValue& value) {
  const std::uint8_t* idx = rec.indices.data();
  const std::uint8_t* val = rec.values.data();
  const std::size_t limit = table.size(), mask = value.face_mask;
  const auto scale = static_cast<float>(value.scale);
  const auto detail_scale = static_cast<float>(value.detail_scale);
  __m128 acc[4] = {_mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
  const auto add = [&](std::size_t e, __m128& sum) {
    const std::size_t k = get_uint(idx + e * W, W);
    if (k >= limit) bad_record("index out of range");
    const bool detail = (k & mask) != 0;
    const float level = detail ? static_cast<float>(static_cast<std::int8_t>(val[e])) * detail_scale
                               : static_cast<float>(val[e]) * scale;
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_load_ps(table[k].rgb), _mm_set1_ps(level)));
  };
  std::size_t e = 0;
  for (; e + 4 <= rec.count; e += 4) {
    add(e, acc[0]);
    add(e + 1, acc[1]);
    add(e + 2, acc[2]);
    add(e + 3, acc[3]);
  }
  for (; e < rec.count; ++e) add(e, acc[0]);
  alignas(16) float sum[4];
  _mm_store_ps(sum, _mm_add_ps(_mm_add_ps(acc[0], acc[1]), _mm_add_ps(acc[2], acc[3])));
  return {sum[0], sum[1], sum[2]};
}

// The 16-bit word at `p` (little-endian, as x86).
std::uint16_t word16(const std::uint8_t* p) {
  std::uint16_t v;
  std::memcpy(&v, p, 2);
  return v;
}

std::uint16_t index16(const std::uint8_t* idx, std::size_t e) {
  return word16(idx + 2 * e);
}

// The largest of `count` little-endian uint16 indices, sixteen at a time: checked before the
// sum reads the shell, so that the sum itself tests nothing.
__attribute__((target("avx2"))) std::uint32_t largest_index16(const std::uint8_t* idx,
                                                              std::size_t count) {
  if (count < 16) {
    std::uint32_t largest = 0;
    for (std::size_t e = 0; e < count; ++e)
      largest = std::max(largest, std::uint32_t{index16(idx, e)});
    return largest;
  }
  const auto* sixteen = reinterpret_cast<const __m256i*>(idx);  // 16 indices in 32 bytes
  __m256i most = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idx + 2 * (count - 16)));
  for (std::size_t e = 0; e + 16 < count; e += 16)
    most = _mm256_max_epu16(most, _mm256_loadu_si256(sixteen + e / 16));
  __m128i half = _mm_max_epu16(_mm256_castsi256_si128(most), _mm256_extracti128_si256(most, 1));
  // The horizontal maximum of eight uint16: minpos of their complements.
  half = _mm_minpos_epu16(_mm_xor_si128(half, _mm_set1_epi16(-1)));
  return 0xffffu - static_cast<std::uint32_t>(_mm_cvtsi128_si32(half) & 0xffff);
}

// The texels of entries e and e + 1 in one register.
__attribute__((target("avx2"))) __m256 texel_pair(const ShellTexel* texel, const std::uint8_t* idx,
                                                  std::size_t e) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(texel[index16(idx, e)].rgb)),
                              _mm_load_ps(texel[index16(idx, e + 1)].rgb), 1);
}

// Eight uint8 levels as floats.
__attribute__((target("avx2"))) __m256 levels_as_floats(std::uint64_t eight) {
  return _mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(eight))));
}

// Eight bytes from p (unaligned).
std::uint64_t eight_bytes(const std::uint8_t* p) {
  std::uint64_t eight;
  std::memcpy(&eight, p, 8);
  return eight;
}

// A pulse record with 2-byte indices (the default N = 32; nearly every record of a room seen
// through a window), with AVX2 and FMA: the indices checked at once, then two entries a step,
// their texels in one 8-float register and their levels spread from eight converted at a time
// by a permute, multiplied-added into four accumulators; the record's scale applied once at the end
// (Σ q·S/255·L = S/255·Σ q·L). Against the generic loop (a range test, a select on the entry's kind
// and a scale multiply an entry), the window-mini sky frame's sum ran 15.2-15.9 -> 11.8-12.3
// ms, 11.3-11.5 with the tail's levels read as below (docs/performance.md). Confining the lookups
// to 16 kB of the 96 kB shell changed nothing: the loop is bound by its instructions, not the
// cache. Test: CubemapEncoding.PulseDotOfEveryLengthEqualsDenseDotTo1e6AndChecksEveryIndex.
__attribute__((target("avx2,fma"))) Rgb pulse_dot16_avx2(const CubemapRecord& rec,
                                                         const std::vector<ShellTexel>& table,
                                                         float scale) {
  const std::uint8_t* idx = rec.indices.data();
  const std::uint8_t* val = rec.values.data();
  const std::size_t count = rec.count;
  if (largest_index16(idx, count) >= table.size()) bad_record("index out of range");
  const ShellTexel* texel = table.data();
  const __m256i spread[4] = {
      _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3),
      _mm256_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5), _mm256_setr_epi32(6, 6, 6, 6, 7, 7, 7, 7)};
  // Four accumulators, as an FMA waits four cycles on its accumulator (two measured the same).
  __m256 acc[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(),
                   _mm256_setzero_ps()};
  std::size_t e = 0;
  for (; e + 8 <= count; e += 8) {
    const __m256 levels = levels_as_floats(eight_bytes(val + e));
    for (int j = 0; j < 4; ++j)
      acc[j] = _mm256_fmadd_ps(texel_pair(texel, idx, e + 2 * static_cast<std::size_t>(j)),
                               _mm256_permutevar8x32_ps(levels, spread[j]), acc[j]);
  }
  // The last 0-7 entries: whole pairs into the accumulators, then one texel alone. Their
  // levels are read as the eight bytes that end the record (a record of m ≥ 1 entries holds
  // 7 + 3m ≥ 8 bytes) and shifted down, instead of a call to copy 0-7 bytes a record (the sum 3 %
  // faster).
  const std::size_t rest = count - e;
  const __m256 levels =
      levels_as_floats(rest == 0 ? 0 : eight_bytes(val + count - 8) >> (8 * (8 - rest)));
  for (int j = 0; e + 2 <= count; e += 2, ++j)
    acc[j] = _mm256_fmadd_ps(texel_pair(texel, idx, e), _mm256_permutevar8x32_ps(levels, spread[j]),
                             acc[j]);
  const __m256 all = _mm256_add_ps(_mm256_add_ps(acc[0], acc[1]), _mm256_add_ps(acc[2], acc[3]));
  __m128 sum = _mm_add_ps(_mm256_castps256_ps128(all), _mm256_extractf128_ps(all, 1));
  if (e < count)
    sum = _mm_fmadd_ps(_mm_load_ps(texel[index16(idx, e)].rgb),
                       _mm_set1_ps(static_cast<float>(val[e])), sum);
  alignas(16) float out[4];
  _mm_store_ps(out, _mm_mul_ps(sum, _mm_set1_ps(scale)));
  return {out[0], out[1], out[2]};
}

// Σ of eight floats.
__attribute__((target("avx2"))) float horizontal_sum(__m256 v) {
  __m128 s = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  s = _mm_add_ps(s, _mm_movehl_ps(s, s));
  s = _mm_add_ss(s, _mm_movehdup_ps(s));
  return _mm_cvtss_f32(s);
}

// Σ over a run record's cells of level × the shell's cells, per channel (the record's scale not
// applied), with AVX2 and FMA for 2-byte starts and lengths: `runs` (start, length) pairs at
// `table`, then `levels` levels. Each run eight cells at a time: their levels converted at once
// and multiplied-added with eight consecutive floats of each of the shell's planes (no lookup,
// no permute). A run's last 1-7 levels are the eight bytes that end them shifted down (the
// record's header lies before its levels, so the bytes read stay inside it), and the planes'
// padding keeps the cells read past a run that ends the cubemap inside (their levels are 0). The
// whole eights and the last few go to separate sums. Measured on window-mini's records, one
// core, through dot_receiver_cubemap (docs/performance.md): 11.3-11.6 ms against 13.5 for the
// same cells as pulse records, 9.2–9.3 ms by blocks through add_receiver_cubemaps (~3.5 of it
// streaming and parsing the records). Taking each run's first sixteen cells as two eights
// without a branch on its length, to spare the mispredicted loop exits, ran slower (15.0 ms).
// Test:
// CubemapEncoding.RunDotOfEveryLengthAndGapEqualsDenseDotTo1e6AndChecksEveryRun.
__attribute__((target("avx2,fma"))) inline Rgb runs_sum16_avx2(const std::uint8_t* table,
                                                               std::size_t runs,
                                                               const std::uint8_t* level,
                                                               std::size_t levels,
                                                               const ShellCubemap& shell) {
  const std::size_t limit = cell_count(shell.n);
  const float* plane[3] = {shell.planes[0].data(), shell.planes[1].data(), shell.planes[2].data()};
  __m256 whole[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  __m256 last[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  std::size_t end = 0, used = 0;
  for (std::size_t j = 0; j < runs; ++j) {
    const std::size_t start = word16(table + 4 * j), length = word16(table + 4 * j + 2);
    check_run(start, length, end, levels - used, limit);
    std::size_t i = 0;
    for (; i + 8 <= length; i += 8) {
      const __m256 q = levels_as_floats(eight_bytes(level + i));
      for (int c = 0; c < 3; ++c)
        whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + start + i), whole[c]);
    }
    if (i < length) {
      const __m256 q =
          levels_as_floats(eight_bytes(level + length - 8) >> (8 * (8 - (length - i))));
      for (int c = 0; c < 3; ++c)
        last[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + start + i), last[c]);
    }
    level += length;
    used += length;
    end = start + length;
  }
  if (used != levels) bad_record("runs hold fewer cells than the record's levels");
  return {horizontal_sum(_mm256_add_ps(whole[0], last[0])),
          horizontal_sum(_mm256_add_ps(whole[1], last[1])),
          horizontal_sum(_mm256_add_ps(whole[2], last[2]))};
}

// The same on any processor and index width.
Rgb runs_dot(const CubemapRecord& rec, const ShellCubemap& shell) {
  float sum[3] = {0, 0, 0};
  for_each_run_cell(rec, shell.n, [&](std::size_t k, std::uint8_t q) {
    for (int c = 0; c < 3; ++c) sum[c] += static_cast<float>(q) * shell.planes[c][k];
  });
  return {sum[0], sum[1], sum[2]};
}

// The rows of one rectangle, K = ⌈width/8⌉ steps of eight cells a row (1 ≤ K ≤ 4), added into
// `whole` (the first K − 1 steps) and `last` (the last, its 1-8 levels the eight bytes that end
// the row shifted down: the record's header lies before them). `level` is left after the
// rectangle's levels. K a constant, so a row is straight-line code and only the row loop
// branches.
template <std::size_t K>
[[gnu::always_inline]] inline __attribute__((target("avx2,fma"))) void add_rectangle_rows(
    const std::uint8_t*& level, std::size_t width, std::size_t height, std::size_t cell,
    std::size_t n, const float* const (&plane)[3], __m256 (&whole)[3], __m256 (&last)[3]) {
  const std::size_t shift = 8 * (8 * K - width);
  for (std::size_t y = 0; y < height; ++y, level += width, cell += n) {
    for (std::size_t b = 0; b + 1 < K; ++b) {
      const __m256 q = levels_as_floats(eight_bytes(level + 8 * b));
      for (int c = 0; c < 3; ++c)
        whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + 8 * b), whole[c]);
    }
    const __m256 q = levels_as_floats(eight_bytes(level + width - 8) >> shift);
    for (int c = 0; c < 3; ++c)
      last[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + 8 * (K - 1)), last[c]);
  }
}

// Σ over a rectangle record's cells of level × the shell's cells, per channel (the record's
// scale not applied), with AVX2 and FMA: `rectangles` checked headers of five bytes at
// `header`, then their levels. Each rectangle's rows by add_rectangle_rows for its number of
// eights (faces of up to 32 cells: N = 32, the default, and smaller; wider rows by the runs'
// loop of eights). The planes' padding keeps the cells read past a row that ends the cubemap
// inside (their levels are 0 and the cells after a row's end finite). Always inlined: a call a
// record from add_records_avx2 cost a tenth of the sum. Measured on window-mini's records
// through add_receiver_cubemaps, one core (docs/performance.md, "Face rectangles"): 6.0 ms,
// against 9.1 ms for the same receivers as runs and 6.75 ms with a loop of eights a row in
// place of the constant. Test:
// CubemapEncoding.RectangleDotOfEveryWidthAndPlaceEqualsDenseDotTo1e6AndChecksEveryRectangle.
[[gnu::always_inline]] inline __attribute__((target("avx2,fma"))) Rgb rectangles_sum_avx2(
    const std::uint8_t* header, std::size_t rectangles, const std::uint8_t* level,
    const ShellCubemap& shell) {
  const std::size_t n = static_cast<std::size_t>(shell.n), nn = n * n;
  const float* const plane[3] = {shell.planes[0].data(), shell.planes[1].data(),
                                 shell.planes[2].data()};
  __m256 whole[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  __m256 last[3] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
  for (std::size_t j = 0; j < rectangles; ++j, header += 5) {
    const std::size_t width = header[3] + std::size_t{1}, height = header[4] + std::size_t{1};
    const std::size_t cell = header[0] * nn + header[2] * n + header[1];
    switch ((width + 7) / 8) {
      case 1:
        add_rectangle_rows<1>(level, width, height, cell, n, plane, whole, last);
        break;
      case 2:
        add_rectangle_rows<2>(level, width, height, cell, n, plane, whole, last);
        break;
      case 3:
        add_rectangle_rows<3>(level, width, height, cell, n, plane, whole, last);
        break;
      case 4:
        add_rectangle_rows<4>(level, width, height, cell, n, plane, whole, last);
        break;
      default:
        for (std::size_t y = 0; y < height; ++y, level += width) {
          const std::size_t eights = width & ~std::size_t{7};
          for (std::size_t x = 0; x < width; x += 8) {
            const std::uint64_t bytes =
                x < eights ? eight_bytes(level + x)
                           : eight_bytes(level + width - 8) >> (8 * (8 - (width - eights)));
            const __m256 q = levels_as_floats(bytes);
            for (int c = 0; c < 3; ++c)
              whole[c] = _mm256_fmadd_ps(q, _mm256_loadu_ps(plane[c] + cell + y * n + x), whole[c]);
          }
        }
    }
  }
  return {horizontal_sum(_mm256_add_ps(whole[0], last[0])),
          horizontal_sum(_mm256_add_ps(whole[1], last[1])),
          horizontal_sum(_mm256_add_ps(whole[2], last[2]))};
}

// rectangles_sum_avx2 for one record, not inlined (dot_receiver_cubemap is built for any
// processor).
__attribute__((target("avx2,fma"))) Rgb rectangles_dot_avx2(const CubemapRecord& rec,
                                                            const ShellCubemap& shell) {
  return rectangles_sum_avx2(rec.indices.data(), rec.rectangles, rec.values.data(), shell);
}

// The same on any processor.
Rgb rectangles_dot(const CubemapRecord& rec, const ShellCubemap& shell) {
  float sum[3] = {0, 0, 0};
  for_each_rectangle_cell(rec, shell.n, [&](std::size_t k, std::uint8_t q) {
    for (int c = 0; c < 3; ++c) sum[c] += static_cast<float>(q) * shell.planes[c][k];
  });
  return {sum[0], sum[1], sum[2]};
}

// `radiance` as floats into `out`, reusing its storage.
void to_texels(const std::vector<Rgb>& radiance, std::vector<ShellTexel>& out) {
  out.resize(radiance.size());
  for (std::size_t k = 0; k < radiance.size(); ++k) {
    out[k].rgb[0] = static_cast<float>(radiance[k].r);
    out[k].rgb[1] = static_cast<float>(radiance[k].g);
    out[k].rgb[2] = static_cast<float>(radiance[k].b);
  }
}

}  // namespace

EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out,
                                        CubemapEncodeScratch& scratch) {
  check_face_size(n);
  if (cells.size() != cell_count(n))
    throw std::invalid_argument("cubemap encoding: " + std::to_string(cells.size()) +
                                " cells, expected 6·N² = " + std::to_string(cell_count(n)));
  if (!(options.threshold >= 0.0 && options.threshold <= 1.0))
    throw std::invalid_argument("cubemap encoding: threshold outside [0, 1]");
  double vmax = 0.0;
  for (double v : cells) {
    if (!(v >= 0.0 && std::isfinite(v)))
      throw std::invalid_argument("cubemap encoding: cell value negative or not finite");
    vmax = std::max(vmax, v);
  }
  EncodedReceiver result;
  if (vmax == 0.0) {
    out.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kEmpty));
    result.bytes = result.pulse_bytes = result.haar_bytes = result.runs_bytes = 1;
    result.rectangles_bytes = cubemap_rectangles_fit(n) ? 1 : 0;
    return result;
  }

  const auto none = [](std::size_t, long) {};
  Quantiser pulse;
  pulse.scale = scale_at_least(vmax);
  pulse.threshold = options.threshold;
  const std::size_t pulse_count = for_each_kept(cells, pulse, none);

  std::vector<double>& amp = scratch.coefficients;
  amp.assign(cells.begin(), cells.end());
  scratch.row.resize(n);
  haar2d_forward_faces(amp, n, scratch.row);
  to_amplitudes(amp, n);
  Quantiser haar;
  haar.face_mask = std::size_t(n) * n - 1;
  haar.threshold = options.threshold;
  double mean_max = 0.0, detail_max = 0.0;
  for (std::size_t k = 0; k < amp.size(); ++k) {
    if (haar.is_detail(k))
      detail_max = std::max(detail_max, std::abs(amp[k]));
    else
      mean_max = std::max(mean_max, amp[k]);
  }
  haar.scale = scale_at_least(mean_max);
  haar.detail_scale = scale_at_least(detail_max);
  const std::size_t haar_count = for_each_kept(amp, haar, none);

  const std::size_t run_levels = find_runs(n, cells, pulse, scratch.runs);
  result.pulse_bytes = cubemap_record_bytes(n, CubemapCodeKind::kPulse, pulse_count);
  result.haar_bytes = cubemap_record_bytes(n, CubemapCodeKind::kHaar, haar_count);
  result.runs_bytes =
      cubemap_record_bytes(n, CubemapCodeKind::kRuns, run_levels, scratch.runs.size() / 2);
  std::size_t rectangles = 0;
  const std::size_t rectangle_levels =
      cubemap_rectangles_fit(n) ? find_rectangles(n, cells, pulse, scratch.rectangles, rectangles)
                                : 0;
  result.rectangles_bytes =
      cubemap_rectangles_fit(n)
          ? cubemap_record_bytes(n, CubemapCodeKind::kRectangles, rectangle_levels, rectangles)
          : 0;
  CubemapCodeKind kind = CubemapCodeKind::kRuns;
  switch (options.choice) {
    case CubemapBasisChoice::kSmaller: {
      std::size_t smallest = result.runs_bytes;
      if (result.rectangles_bytes != 0 && result.rectangles_bytes <= smallest) {
        kind = CubemapCodeKind::kRectangles;
        smallest = result.rectangles_bytes;
      }
      if (result.pulse_bytes < smallest) {
        kind = CubemapCodeKind::kPulse;
        smallest = result.pulse_bytes;
      }
      if (result.haar_bytes < smallest) kind = CubemapCodeKind::kHaar;
      break;
    }
    case CubemapBasisChoice::kRectangles:
      if (!cubemap_rectangles_fit(n))
        throw std::invalid_argument(
            "cubemap encoding: rectangles for faces of more than 256 cells");
      kind = CubemapCodeKind::kRectangles;
      break;
    case CubemapBasisChoice::kPulse:
      kind = CubemapCodeKind::kPulse;
      break;
    case CubemapBasisChoice::kHaar:
      kind = CubemapCodeKind::kHaar;
      break;
    case CubemapBasisChoice::kRuns:
      break;
  }
  const std::size_t before = out.size();
  result.kind = kind;
  if (kind == CubemapCodeKind::kHaar) {
    result.scale = static_cast<float>(haar.scale);
    result.detail_scale = static_cast<float>(haar.detail_scale);
    write_record(n, kind, haar, amp, haar_count, out);
  } else if (kind == CubemapCodeKind::kPulse) {
    result.scale = static_cast<float>(pulse.scale);
    write_record(n, kind, pulse, cells, pulse_count, out);
  } else if (kind == CubemapCodeKind::kRuns) {
    result.scale = static_cast<float>(pulse.scale);
    write_runs_record(n, pulse, cells, scratch.runs, run_levels, out);
  } else {
    result.scale = static_cast<float>(pulse.scale);
    write_rectangles_record(n, pulse, cells, scratch.rectangles, rectangles, out);
  }
  result.bytes = out.size() - before;
  return result;
}

EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out) {
  CubemapEncodeScratch scratch;
  return encode_receiver_cubemap(n, cells, options, out, scratch);
}

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

void prepare_shell_cubemap(int n, std::span<const Rgb> radiance, ShellCubemap& shell) {
  check_face_size(n);
  if (radiance.size() != cell_count(n))
    throw std::invalid_argument("shell cubemap: radiance must hold 6·N² cells");
  shell.n = n;
  shell.cells.assign(radiance.begin(), radiance.end());
  shell.haar.assign(radiance.begin(), radiance.end());
  std::vector<Rgb> row(n);
  haar2d_forward_faces(std::span<Rgb>(shell.haar), n, std::span<Rgb>(row));
  const std::size_t nn = std::size_t(n) * n;
  for (std::size_t start = 0; start < shell.haar.size(); start += nn)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        shell.haar[start + std::size_t(r) * n + c] *= haar2d_support(n, r, c);
  to_texels(shell.cells, shell.cells_float);
  to_texels(shell.haar, shell.haar_float);
  for (std::vector<float>& plane : shell.planes)
    plane.assign(radiance.size() + ShellCubemap::kPlanePadding, 0.0f);
  for (std::size_t k = 0; k < radiance.size(); ++k) {
    shell.planes[0][k] = static_cast<float>(radiance[k].r);
    shell.planes[1][k] = static_cast<float>(radiance[k].g);
    shell.planes[2][k] = static_cast<float>(radiance[k].b);
  }
}

ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance) {
  ShellCubemap shell;
  prepare_shell_cubemap(n, radiance, shell);
  return shell;
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
// parse_cubemap_record took half of window-mini's records' sum; with the loop here 9.2 → 8.7 ms on
// one core, 9.2–9.3 ms since the header's checks are read_runs_header's, written once for both
// (inlined; a call was 30 ms).
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

void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver) {
  ++stats.receivers;
  stats.bytes += receiver.bytes;
  stats.all_pulse_bytes += receiver.pulse_bytes;
  stats.all_haar_bytes += receiver.haar_bytes;
  stats.all_runs_bytes += receiver.runs_bytes;
  stats.all_rectangles_bytes += receiver.rectangles_bytes;
  switch (receiver.kind) {
    case CubemapCodeKind::kEmpty:
      ++stats.empty;
      break;
    case CubemapCodeKind::kPulse:
      ++stats.pulse;
      stats.pulse_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kHaar:
      ++stats.haar;
      stats.haar_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kRuns:
      ++stats.runs;
      stats.runs_bytes += receiver.bytes;
      break;
    case CubemapCodeKind::kRectangles:
      ++stats.rectangles;
      stats.rectangles_bytes += receiver.bytes;
      break;
  }
}

void add_stats(CubemapEncodingStats& sum, const CubemapEncodingStats& part) {
  sum.receivers += part.receivers;
  sum.empty += part.empty;
  sum.pulse += part.pulse;
  sum.haar += part.haar;
  sum.runs += part.runs;
  sum.rectangles += part.rectangles;
  sum.bytes += part.bytes;
  sum.pulse_bytes += part.pulse_bytes;
  sum.haar_bytes += part.haar_bytes;
  sum.runs_bytes += part.runs_bytes;
  sum.rectangles_bytes += part.rectangles_bytes;
  sum.all_pulse_bytes += part.all_pulse_bytes;
  sum.all_haar_bytes += part.all_haar_bytes;
  sum.all_runs_bytes += part.all_runs_bytes;
  sum.all_rectangles_bytes += part.all_rectangles_bytes;
}

CubemapEncodingStats cubemap_encoding_stats(int n, std::span<const std::uint8_t> records) {
  CubemapEncodingStats stats;
  for (std::size_t offset = 0; offset < records.size();) {
    const CubemapRecord rec = parse_cubemap_record(n, records.subspan(offset));
    EncodedReceiver r;
    r.kind = rec.kind;
    r.bytes = rec.bytes;
    add_receiver(stats, r);
    offset += rec.bytes;
  }
  stats.all_pulse_bytes = stats.all_haar_bytes = stats.all_runs_bytes = 0;
  stats.all_rectangles_bytes = 0;
  return stats;
}

double bytes_per_receiver(const CubemapEncodingStats& stats) {
  return stats.receivers == 0 ? 0.0 : static_cast<double>(stats.bytes) / stats.receivers;
}

}  // namespace relight
