// Per-receiver compression of the direct portal component, as Yue et al. 2009
// (Yue et al. 2009 §3.4, §4.1.2): each receiver's cubemap of
// light arriving through a portal (6·N² non-negative transfer weights t, one per cell, in the
// layout of math/cubemap.h, geometry only: the outgoing radiance is Σ_cells t·L_shell) is
// stored in whichever of four records is the smallest, all quantised to 8 bits against
// the receiver's maximum ("we calculate the maximum contribution among all the directions for
// the vertex"):
//  * pulse functions: the non-zero cells, each (cell index, uint8 t/S·255). Best when the
//    portal covers few scattered cells (a far or small window);
//  * pulse runs: the same pulse functions, as runs of consecutive cells (start, length) and one
//    uint8 level a cell. A window covers a patch of each face it is seen on, a run a row of it
//    (window-mini: 11 runs of 9 cells a record), so a run record is half a pulse record and its
//    sum reads eight consecutive cells at a time instead of looking up each (the window sum at
//    the streaming rate). Gaps of at most 2W cells inside a run are stored as
//    zero levels, never more bytes than a new run;
//  * face rectangles: the same pulse functions, as the bounding rectangle of the kept cells on
//    each face they lie on and one uint8 level a cell of it, row by row (the cells outside the
//    window's patch are zero levels). A window's patch fills ~90 % of its rectangles
//    (window-mini and the dragon behind a window), so the record is a fifth smaller than the
//    runs (five bytes a face instead of four a row), and its sum walks rows of one width, eight
//    cells at a time, with no start or length to read and check a row;
//  * per-face Haar wavelets (math/haar.h): the non-zero coefficients, each (index, 8 bits).
//    Best when the portal covers a large smooth region (a receiver near a window).
// The run time (§5, Appendix Eq. 7) never decodes: it transforms the shell's radiance cubemap
// once per state change (ShellCubemap) and then each receiver is a sparse dot product: pulse
// Σ t_cell·L[cell] (over runs and rectangles, the cells' radiance read as planes of consecutive
// floats);
// Haar Σ T_k·H(L)_k, equal to the cell-domain dot product by Parseval (the transform is
// orthonormal).
//
// Haar quantisation. Coefficients are quantised in cell units: the amplitude of coefficient k
// is a_k = T_k / S_k, S_k = haar2d_support (the basis is ±1/S_k on S_k×S_k cells), i.e. the
// face mean for the scaling coefficient and a quarter of a signed sum of the four quadrant
// means for a detail; for t ≥ 0, 0 ≤ mean ≤ max t and |detail| ≤ max t / 2. Quantising in cell
// units (rather than the orthonormal T_k, whose scaling coefficient is N × the mean) keeps the
// fine details, which carry the window's edges, as accurate per cell as the coarse ones, and
// drops a detail only when it changes no cell by more than half a step. The six face means get
// their own scale and unsigned values: they alone decide Σ t̂ (the response to a uniform sky,
// which the floor-illuminance test holds to 2 %), and with the details' scale a face holding a
// sliver of the window would lose its mean to rounding. The shell side folds S_k into its
// transformed radiance (ShellCubemap::haar), so the dot product is one multiply-add per stored
// coefficient.
//
// Record byte layout (little-endian; records are stored back to back, no padding). W, the
// width of a cell or coefficient index and of the count, is 2 (uint16) when 6·N² ≤ 65535
// (N ≤ 64 for powers of two; the default N = 32) and 4 (uint32) otherwise:
//   byte 0     kind: 0 empty, 1 pulse, 2 Haar, 3 pulse runs, 4 face rectangles. An all-zero
//              receiver is this one byte.
//   pulse:     float32 S ≥ max t | W count m | m·W indices | m uint8 q: t = q·S/255
//   runs:      float32 S ≥ max t | W run count r | W level count m | r × (W start, W length)
//              | m uint8 q, the runs' cells in order: t = q·S/255. 1 ≤ r ≤ m ≤ 6·N²; each
//              length ≥ 1, the lengths sum to m, a run ends by 6·N² and starts at or after the
//              previous run's end
//   rectangles (N ≤ 256): float32 S ≥ max t | uint8 rectangle count f | f × (uint8 face, x0,
//              y0, w − 1, h − 1) | m = Σ w·h uint8 q, each rectangle's cells row by row (cell
//              (face·N + y0 + row)·N + x0 + column): t = q·S/255. 1 ≤ f ≤ 6, faces strictly
//              increasing, x0 + w ≤ N and y0 + h ≤ N
//   Haar:      float32 S₀ ≥ max face mean | float32 S_d ≥ max |detail amplitude| (0 when
//              there is none) | W count m | m·W indices | m values: for a face mean (index
//              in face 0) uint8 q, a = q·S₀/255; for a detail int8 q ∈ [−127, 127],
//              a = q·S_d/127; T = a·S_k
// Scales are the float nearest above the double maximum (quantised values never clip).
// Indices are strictly increasing: a cell's (face·N + row)·N + column; for Haar the
// coefficient (r, c) of face f is at the same (f·N + r)·N + c (math/haar.h's Mallat layout).
// A record is 1 byte (empty), 1 + 4 + W + m·(W + 1) bytes (pulse: 7 + 3m for N ≤ 64),
// 1 + 8 + W + m·(W + 1) bytes (Haar: 11 + 3m), 1 + 4 + 2W + 2W·r + m bytes (runs: 9 + 4r + m)
// or 6 + 5f + m bytes (rectangles); 1 ≤ m ≤ 6·N².
//
// Error bounds (τ the relative threshold, default 0; each value is rounded to the nearest
// level or dropped when it rounds to 0 or lies below τ × its scale):
//  * pulse, runs and rectangles, per cell: |t̂ − t| ≤ ε_p·S, ε_p = max(τ, 1/510).
//  * Haar, per coefficient amplitude: face means |â − a| ≤ e₀ = max(τ, 1/510)·S₀, details
//    ≤ e_d = max(τ, 1/254)·S_d; per cell |t̂ − t| ≤ e₀ + 3·log2 N·e_d, since each cell lies
//    under one scaling function and three details per level, each of magnitude 1/S_k there
//    (a worst case: errors of independent coefficients mostly cancel). For t ≥ 0,
//    S₀ ≤ max t and S_d ≤ max t / 2, so this is ≤ (1/510 + 3·log2 N/508)·max t at τ = 0
//    (≈ 0.032·max t at N = 32).
//  * Σ t̂ vs Σ t (a uniform shell): ≤ N²·e₀ per face holding a mean (details sum to 0).
//  * dot product with radiance L (each channel): pulse, runs, rectangles ≤ ε_p·S·Σ_{t>0} |L|; Haar
//    ≤ Σ_k e_k·|S_k·H(L)_k| (ShellCubemap::haar; e_k = e₀ or e_d), by Parseval.
// Decoded Haar cells can be slightly negative; the dot product is linear and keeps them.
//
// The code: cubemap_encoding.cpp chooses and writes a receiver's record, with each kind's encoding
// in cubemap_pulse.cpp (pulse and Haar records share its writer), cubemap_haar.cpp,
// cubemap_runs.cpp and cubemap_rectangles.cpp; cubemap_sum.cpp parses, decodes and sums the
// records, with each kind's reader and sums in cubemap_pulse_sum.h, cubemap_runs_sum.h and
// cubemap_rectangles_sum.h; cubemap_shell.cpp prepares the shell and cubemap_stats.cpp counts the
// records.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/rgb.h"

namespace relight {

enum class CubemapCodeKind : std::uint8_t {
  kEmpty = 0,
  kPulse = 1,
  kHaar = 2,
  kRuns = 3,
  kRectangles = 4
};

// Which record the encoder writes: the smallest (ties go to rectangles, then runs, then pulse:
// the cheapest to sum first, and pulse functions are exact to their 8 bits where Haar's details
// add up), or one forced (to report the alternatives, or for tests; rectangles need N ≤ 256).
enum class CubemapBasisChoice { kSmaller, kPulse, kHaar, kRuns, kRectangles };

struct CubemapEncodeOptions {
  // Relative threshold τ ∈ [0, 1]: pulse drops cells t < τ·S; Haar drops face means below τ·S₀
  // and details |a| < τ·S_d. 0 keeps everything that does not round to 0 (lossless up to the
  // 8-bit quantisation).
  double threshold = 0.0;
  CubemapBasisChoice choice = CubemapBasisChoice::kSmaller;
};

// Bytes of an index or count in a record for face size N (2 or 4, see above).
constexpr std::size_t cubemap_code_index_bytes(int n) {
  return std::size_t{6} * n * n <= 65535 ? 2 : 4;
}
// Whether face rectangles can hold a face of size N (their coordinates are bytes).
constexpr bool cubemap_rectangles_fit(int n) {
  return n <= 256;
}
// Bytes of a record of m entries (m = 0: the 1-byte empty record, whatever the kind); for runs
// and rectangles, m levels in `parts` runs or rectangles.
constexpr std::size_t cubemap_record_bytes(int n, CubemapCodeKind kind, std::size_t entries,
                                           std::size_t parts = 0) {
  if (entries == 0 || kind == CubemapCodeKind::kEmpty) return 1;
  const std::size_t w = cubemap_code_index_bytes(n);
  if (kind == CubemapCodeKind::kRuns) return 1 + 4 + 2 * w + 2 * w * parts + entries;
  if (kind == CubemapCodeKind::kRectangles) return 1 + 4 + 1 + 5 * parts + entries;
  const std::size_t scales = kind == CubemapCodeKind::kHaar ? 8 : 4;
  return 1 + scales + w * (entries + 1) + entries;
}

// What encoding one receiver wrote, and what each basis would have cost.
struct EncodedReceiver {
  CubemapCodeKind kind = CubemapCodeKind::kEmpty;
  std::size_t bytes = 0;             // appended to the buffer
  std::size_t pulse_bytes = 0;       // the pulse record's size
  std::size_t haar_bytes = 0;        // the Haar record's size
  std::size_t runs_bytes = 0;        // the run record's size
  std::size_t rectangles_bytes = 0;  // the rectangle record's size (0 when N > 256: none)
  float scale = 0;  // pulse, runs or rectangles S, or Haar S₀, of the record written (0: empty)
  float detail_scale = 0;  // Haar S_d
};

// Reused between receivers so that encoding allocates nothing once warm.
struct CubemapEncodeScratch {
  std::vector<double> coefficients;
  std::vector<double> row;
  std::vector<std::uint32_t> runs;  // start, end of each run
  // The kept cells' bounding rectangle on each face: x0, y0, x1, y1 inclusive (x0 > x1: none).
  std::array<std::array<int, 4>, 6> rectangles{};
};

// Appends one receiver's record to `out`. cells: 6·N² finite values ≥ 0; N a power of two.
// std::invalid_argument otherwise.
EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out,
                                        CubemapEncodeScratch& scratch);
EncodedReceiver encode_receiver_cubemap(int n, std::span<const double> cells,
                                        const CubemapEncodeOptions& options,
                                        std::vector<std::uint8_t>& out);

// A parsed record; spans point into the bytes given to parse_cubemap_record.
struct CubemapRecord {
  CubemapCodeKind kind = CubemapCodeKind::kEmpty;
  float scale = 0;                        // pulse, runs and rectangles S, Haar S₀
  float detail_scale = 0;                 // Haar S_d
  std::size_t count = 0;                  // entries (runs, rectangles: levels)
  std::size_t runs = 0;                   // runs only
  std::size_t rectangles = 0;             // rectangles only
  std::span<const std::uint8_t> indices;  // count·W bytes, little-endian (runs: the runs'
                                          // runs·2·W bytes of start, length; rectangles: their
                                          // 5·rectangles bytes of face, x0, y0, w − 1, h − 1)
  std::span<const std::uint8_t> values;   // count bytes: uint8, or int8 for Haar details
  std::size_t bytes = 1;                  // the whole record
};

// The record starting at bytes[0] (the span may run on into later records). InputError for an
// unknown kind, a bad scale or count, or a truncated record; indices and runs are checked by
// the users below.
CubemapRecord parse_cubemap_record(int n, std::span<const std::uint8_t> bytes);

// Decodes the record at bytes[0] into 6·N² cell values; returns the record's size. scratch
// holds at least N values. InputError for an index out of range or not increasing, runs out of
// range, overlapping or not covering the levels, or rectangles beyond their face or out of
// order.
std::size_t decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes,
                                    std::span<double> cells, std::span<double> scratch);
std::vector<double> decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes);

// The shell's radiance cubemap in both bases, rebuilt once per state change (paper §5:
// "cubemap representation and wavelet bases").
// The hot loop reads them as floats, one 16-byte texel a cell (the window sum at the streaming
// rate; a double texel is 24 bytes and three separate multiply-adds).
struct alignas(16) ShellTexel {
  float rgb[4] = {0, 0, 0, 0};  // r, g, b, 0
};
struct ShellCubemap {
  int n = 0;
  std::vector<Rgb> cells;  // radiance per cell (pulse domain)
  std::vector<Rgb> haar;   // per face: orthonormal Haar coefficient k × S_k
  std::vector<ShellTexel> cells_float, haar_float;  // the same as floats
  // The cells as three planes of floats (r, g, b) for the runs' and rectangles' sums, which read
  // eight consecutive cells at a time: 6·N² + kPlanePadding each, the padding zero, so that the
  // cells read past a run or row that ends the cubemap stay inside (their levels are 0).
  static constexpr std::size_t kPlanePadding = 8;
  std::vector<float> planes[3];
};
// Fills `shell` from 6·N² radiance cells, reusing its storage.
void prepare_shell_cubemap(int n, std::span<const Rgb> radiance, ShellCubemap& shell);
ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance);

// Σ_cells t̂·L for the record at bytes[0] (Eq. 7), as a sparse dot product in the record's
// basis, summed in float (the entries are 8-bit: float's 2⁻²⁴ is far below their 1/510).
// InputError for an index out of range, runs out of range, overlapping or not covering the
// levels, or rectangles beyond their face or out of order.
Rgb dot_receiver_cubemap(std::span<const std::uint8_t> bytes, const ShellCubemap& shell);

// For each i < offsets.size() − 1, adds the record at bytes [offsets[i], offsets[i + 1]) of
// `records`'s Σ t̂·L (dot_receiver_cubemap's, to float rounding) to red[i], green[i], blue[i]: a
// block of receivers' records in one call, run and rectangle records parsed and checked inline.
// `read_next`: bytes the caller reads right after (the block's indirect transfer), whose cache
// lines are prefetched a few a record, so that they arrive while the records — bound by their
// arithmetic, not their bytes — are summed (measured: docs/decisions.md); the sums are the same
// floats (CubemapEncoding.BlockOfRecordsAddsEachRecordsDotExactly).
// InputError for offsets out of order or beyond `records`, or a malformed record.
void add_receiver_cubemaps(std::span<const std::uint8_t> records,
                           std::span<const std::uint64_t> offsets, const ShellCubemap& shell,
                           std::span<float> red, std::span<float> green, std::span<float> blue,
                           std::span<const std::byte> read_next = {});

// Bytes and basis split over a set of receivers.
struct CubemapEncodingStats {
  std::size_t receivers = 0, empty = 0, pulse = 0, haar = 0, runs = 0, rectangles = 0;
  std::size_t bytes = 0;  // all records
  // Records of each kind.
  std::size_t pulse_bytes = 0, haar_bytes = 0, runs_bytes = 0, rectangles_bytes = 0;
  // Had every receiver used one kind (add_receiver only; empty: 1 byte; rectangles: 0 when
  // N > 256).
  std::size_t all_pulse_bytes = 0, all_haar_bytes = 0, all_runs_bytes = 0, all_rectangles_bytes = 0;
};
void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver);
// `part`'s counts and bytes added to `sum`'s (chunks or ranks of one portal).
void add_stats(CubemapEncodingStats& sum, const CubemapEncodingStats& part);
// Walks a buffer of back-to-back records (all_*_bytes stay 0: the alternatives are unknown).
CubemapEncodingStats cubemap_encoding_stats(int n, std::span<const std::uint8_t> records);
double bytes_per_receiver(const CubemapEncodingStats& stats);

}  // namespace relight
