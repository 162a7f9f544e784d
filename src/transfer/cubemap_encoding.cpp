// Pulse / per-face Haar encoding of a receiver's portal cubemap, 8-bit quantised, and the
// run-time sparse dot product (paper 000 §4.1.2, §5, Eq. 7); layout and bounds in
// cubemap_encoding.h.
#include "transfer/cubemap_encoding.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
      for (int c = 0; c < n; ++c) coefficients[start + r * n + c] /= haar2d_support(n, r, c);
}

template <class F>
std::size_t count_kept(std::span<const double> values, double scale, double levels,
                       double threshold, F&& visit) {
  std::size_t m = 0;
  const double cut = threshold * scale;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double v = values[k];
    if (v == 0.0 || std::abs(v) < cut) continue;
    const long q = std::lround(v / scale * levels);
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

void write_record(int n, CubemapCodeKind kind, float scale, std::span<const double> values,
                  double levels, double threshold, std::vector<std::uint8_t>& out,
                  std::size_t count) {
  const std::size_t w = cubemap_code_index_bytes(n);
  out.push_back(static_cast<std::uint8_t>(kind));
  put_uint(out, std::bit_cast<std::uint32_t>(scale), 4);
  put_uint(out, static_cast<std::uint32_t>(count), w);
  count_kept(values, scale, levels, threshold,
             [&](std::size_t k, long) { put_uint(out, static_cast<std::uint32_t>(k), w); });
  count_kept(values, scale, levels, threshold, [&](std::size_t, long q) {
    out.push_back(static_cast<std::uint8_t>(static_cast<std::int8_t>(q)));  // uint8 or int8
  });
}

[[noreturn]] void bad_record(const std::string& reason) {
  throw InputError("cubemap record: " + reason);
}

// Calls visit(index, value byte) for each entry, checking indices are increasing and < limit.
template <class F>
void for_each_entry(const CubemapRecord& rec, std::size_t w, std::size_t limit, F&& visit) {
  const std::uint8_t* idx = rec.indices.data();
  std::size_t previous = 0;
  for (std::size_t e = 0; e < rec.count; ++e) {
    const std::size_t k = get_uint(idx + e * w, w);
    if (k >= limit || (e > 0 && k <= previous)) bad_record("index out of range or not increasing");
    previous = k;
    visit(k, rec.values[e]);
  }
}

template <std::size_t W, class Table, class Weight>
Rgb sparse_dot(const CubemapRecord& rec, const Table& table, Weight&& weight) {
  const std::uint8_t* idx = rec.indices.data();
  const std::uint8_t* val = rec.values.data();
  const std::size_t limit = table.size();
  Rgb acc;
  for (std::size_t e = 0; e < rec.count; ++e) {
    const std::size_t k = get_uint(idx + e * W, W);
    if (k >= limit) bad_record("index out of range");
    acc += table[k] * weight(val[e]);
  }
  return acc;
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
    result.bytes = result.pulse_bytes = result.haar_bytes = 1;
    return result;
  }

  const double tau = options.threshold;
  const auto none = [](std::size_t, long) {};
  const float pulse_scale = scale_at_least(vmax);
  const std::size_t pulse_count = count_kept(cells, pulse_scale, kPulseLevels, tau, none);

  std::vector<double>& amp = scratch.coefficients;
  amp.assign(cells.begin(), cells.end());
  scratch.row.resize(n);
  haar2d_forward_faces(amp, n, scratch.row);
  to_amplitudes(amp, n);
  double amax = 0.0;
  for (double a : amp) amax = std::max(amax, std::abs(a));
  const float haar_scale = scale_at_least(amax);
  const std::size_t haar_count = count_kept(amp, haar_scale, kHaarLevels, tau, none);

  result.pulse_bytes = cubemap_record_bytes(n, pulse_count);
  result.haar_bytes = cubemap_record_bytes(n, haar_count);
  const bool haar =
      options.choice == CubemapBasisChoice::kHaar ||
      (options.choice == CubemapBasisChoice::kSmaller && result.haar_bytes < result.pulse_bytes);
  const std::size_t before = out.size();
  if (haar) {
    result.kind = CubemapCodeKind::kHaar;
    result.scale = haar_scale;
    write_record(n, result.kind, haar_scale, amp, kHaarLevels, tau, out, haar_count);
  } else {
    result.kind = CubemapCodeKind::kPulse;
    result.scale = pulse_scale;
    write_record(n, result.kind, pulse_scale, cells, kPulseLevels, tau, out, pulse_count);
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
      kind != static_cast<std::uint8_t>(CubemapCodeKind::kHaar))
    bad_record("unknown kind " + std::to_string(kind));
  rec.kind = static_cast<CubemapCodeKind>(kind);
  const std::size_t w = cubemap_code_index_bytes(n);
  if (bytes.size() < 1 + 4 + w) bad_record("truncated header");
  rec.scale = std::bit_cast<float>(get_uint(bytes.data() + 1, 4));
  if (!(rec.scale > 0.0f && std::isfinite(rec.scale))) bad_record("scale not positive and finite");
  rec.count = get_uint(bytes.data() + 5, w);
  if (rec.count == 0 || rec.count > cell_count(n)) bad_record("entry count out of range");
  rec.bytes = cubemap_record_bytes(n, rec.count);
  if (bytes.size() < rec.bytes) bad_record("truncated entries");
  rec.indices = bytes.subspan(1 + 4 + w, rec.count * w);
  rec.values = bytes.subspan(1 + 4 + w + rec.count * w, rec.count);
  return rec;
}

std::size_t decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes,
                                    std::span<double> cells, std::span<double> scratch) {
  const CubemapRecord rec = parse_cubemap_record(n, bytes);
  if (cells.size() != cell_count(n))
    throw std::invalid_argument("cubemap decoding: output must hold 6·N² cells");
  std::fill(cells.begin(), cells.end(), 0.0);
  const std::size_t w = cubemap_code_index_bytes(n);
  const double s = rec.scale;
  if (rec.kind == CubemapCodeKind::kPulse) {
    for_each_entry(rec, w, cells.size(),
                   [&](std::size_t k, std::uint8_t q) { cells[k] = q * s / kPulseLevels; });
  } else if (rec.kind == CubemapCodeKind::kHaar) {
    const std::size_t nn = std::size_t(n) * n;
    for_each_entry(rec, w, cells.size(), [&](std::size_t k, std::uint8_t q) {
      const std::size_t in_face = k % nn;
      const int support = haar2d_support(n, static_cast<int>(in_face / n), static_cast<int>(in_face % n));
      cells[k] = static_cast<std::int8_t>(q) * s / kHaarLevels * support;
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
      for (int c = 0; c < n; ++c) shell.haar[start + r * n + c] *= haar2d_support(n, r, c);
}

ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance) {
  ShellCubemap shell;
  prepare_shell_cubemap(n, radiance, shell);
  return shell;
}

Rgb dot_receiver_cubemap(std::span<const std::uint8_t> bytes, const ShellCubemap& shell) {
  const CubemapRecord rec = parse_cubemap_record(shell.n, bytes);
  const bool narrow = cubemap_code_index_bytes(shell.n) == 2;
  if (rec.kind == CubemapCodeKind::kPulse) {
    const auto weight = [](std::uint8_t q) { return static_cast<double>(q); };
    const Rgb sum = narrow ? sparse_dot<2>(rec, shell.cells, weight)
                           : sparse_dot<4>(rec, shell.cells, weight);
    return sum * (rec.scale / kPulseLevels);
  }
  if (rec.kind == CubemapCodeKind::kHaar) {
    const auto weight = [](std::uint8_t q) { return static_cast<double>(static_cast<std::int8_t>(q)); };
    const Rgb sum =
        narrow ? sparse_dot<2>(rec, shell.haar, weight) : sparse_dot<4>(rec, shell.haar, weight);
    return sum * (rec.scale / kHaarLevels);
  }
  return {};
}

void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver) {
  ++stats.receivers;
  stats.bytes += receiver.bytes;
  stats.all_pulse_bytes += receiver.pulse_bytes;
  stats.all_haar_bytes += receiver.haar_bytes;
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
  }
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
  stats.all_pulse_bytes = stats.all_haar_bytes = 0;
  return stats;
}

double bytes_per_receiver(const CubemapEncodingStats& stats) {
  return stats.receivers == 0 ? 0.0 : static_cast<double>(stats.bytes) / stats.receivers;
}

}  // namespace relight
