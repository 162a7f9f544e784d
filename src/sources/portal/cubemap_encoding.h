// Per-receiver compression of the direct portal component, as Yue et al. 2009
// (Yue et al. 2009 §3.4, §4.1.2, issue 4 item 3): each receiver's cubemap of
// light arriving through a portal (6·N² non-negative transfer weights t, one per cell, in the
// layout of math/cubemap.h, geometry only: the outgoing radiance is Σ_cells t·L_shell) is
// stored in whichever of two bases gives the smaller record, both quantised to 8 bits against
// the receiver's maximum ("we calculate the maximum contribution among all the directions for
// the vertex"):
//  * pulse functions: the non-zero cells, each (cell index, uint8 t/S·255). Best when the
//    portal covers few cells (a far or small window);
//  * per-face Haar wavelets (math/haar.h): the non-zero coefficients, each (index, 8 bits).
//    Best when the portal covers a large smooth region (a receiver near a window).
// The run time (§5, Appendix Eq. 7) never decodes: it transforms the shell's radiance cubemap
// once per state change (ShellCubemap) and then each receiver is a sparse dot product: pulse
// Σ t_cell·L[cell]; Haar Σ T_k·H(L)_k, equal to the cell-domain dot product by Parseval (the
// transform is orthonormal).
//
// Haar quantisation. Coefficients are quantised in cell units: the amplitude of coefficient k
// is a_k = T_k / S_k, S_k = haar2d_support (the basis is ±1/S_k on S_k×S_k cells), i.e. the
// face mean for the scaling coefficient and a quarter of a signed sum of the four quadrant
// means for a detail; for t ≥ 0, 0 ≤ mean ≤ max t and |detail| ≤ max t / 2. Quantising in cell
// units (rather than the orthonormal T_k, whose scaling coefficient is N × the mean) keeps the
// fine details, which carry the window's edges, as accurate per cell as the coarse ones, and
// drops a detail only when it changes no cell by more than half a step. The six face means get
// their own scale and unsigned values: they alone decide Σ t̂ (the response to a uniform sky,
// issue 4's 2% floor-illuminance test), and with the details' scale a face holding a sliver of
// the window would lose its mean to rounding. The shell side folds S_k into its transformed
// radiance (ShellCubemap::haar), so the dot product is one multiply-add per stored coefficient.
//
// Record byte layout (little-endian; records are stored back to back, no padding). W, the
// width of a cell or coefficient index and of the count, is 2 (uint16) when 6·N² ≤ 65535
// (N ≤ 64 for powers of two; the default N = 32) and 4 (uint32) otherwise:
//   byte 0     kind: 0 empty, 1 pulse, 2 Haar. An all-zero receiver is this one byte.
//   pulse:     float32 S ≥ max t | W count m | m·W indices | m uint8 q: t = q·S/255
//   Haar:      float32 S₀ ≥ max face mean | float32 S_d ≥ max |detail amplitude| (0 when
//              there is none) | W count m | m·W indices | m values: for a face mean (index
//              in face 0) uint8 q, a = q·S₀/255; for a detail int8 q ∈ [−127, 127],
//              a = q·S_d/127; T = a·S_k
// Scales are the float nearest above the double maximum (quantised values never clip).
// Indices are strictly increasing: a cell's (face·N + row)·N + column; for Haar the
// coefficient (r, c) of face f is at the same (f·N + r)·N + c (math/haar.h's Mallat layout).
// A record is 1 byte (empty), 1 + 4 + W + m·(W + 1) bytes (pulse: 7 + 3m for N ≤ 64) or
// 1 + 8 + W + m·(W + 1) bytes (Haar: 11 + 3m); 1 ≤ m ≤ 6·N².
//
// Error bounds (τ the relative threshold, default 0; each value is rounded to the nearest
// level or dropped when it rounds to 0 or lies below τ × its scale):
//  * pulse, per cell: |t̂ − t| ≤ ε_p·S, ε_p = max(τ, 1/510).
//  * Haar, per coefficient amplitude: face means |â − a| ≤ e₀ = max(τ, 1/510)·S₀, details
//    ≤ e_d = max(τ, 1/254)·S_d; per cell |t̂ − t| ≤ e₀ + 3·log2 N·e_d, since each cell lies
//    under one scaling function and three details per level, each of magnitude 1/S_k there
//    (a worst case: errors of independent coefficients mostly cancel). For t ≥ 0,
//    S₀ ≤ max t and S_d ≤ max t / 2, so this is ≤ (1/510 + 3·log2 N/508)·max t at τ = 0
//    (≈ 0.032·max t at N = 32).
//  * Σ t̂ vs Σ t (a uniform shell): ≤ N²·e₀ per face holding a mean (details sum to 0).
//  * dot product with radiance L (each channel): pulse ≤ ε_p·S·Σ_{t>0} |L|; Haar
//    ≤ Σ_k e_k·|S_k·H(L)_k| (ShellCubemap::haar; e_k = e₀ or e_d), by Parseval.
// Decoded Haar cells can be slightly negative; the dot product is linear and keeps them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/rgb.h"

namespace relight {

enum class CubemapCodeKind : std::uint8_t { kEmpty = 0, kPulse = 1, kHaar = 2 };

// Which basis the encoder writes: the smaller record (ties go to pulse, the cheaper and more
// accurate one), or one forced (to report the alternatives, or for tests).
enum class CubemapBasisChoice { kSmaller, kPulse, kHaar };

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
// Bytes of a record of m entries (m = 0: the 1-byte empty record, whatever the kind).
constexpr std::size_t cubemap_record_bytes(int n, CubemapCodeKind kind, std::size_t entries) {
  if (entries == 0 || kind == CubemapCodeKind::kEmpty) return 1;
  const std::size_t scales = kind == CubemapCodeKind::kHaar ? 8 : 4;
  return 1 + scales + cubemap_code_index_bytes(n) * (entries + 1) + entries;
}

// What encoding one receiver wrote, and what each basis would have cost.
struct EncodedReceiver {
  CubemapCodeKind kind = CubemapCodeKind::kEmpty;
  std::size_t bytes = 0;        // appended to the buffer
  std::size_t pulse_bytes = 0;  // the pulse record's size
  std::size_t haar_bytes = 0;   // the Haar record's size
  float scale = 0;              // pulse S or Haar S₀ of the record written (0 for empty)
  float detail_scale = 0;       // Haar S_d
};

// Reused between receivers so that encoding allocates nothing once warm.
struct CubemapEncodeScratch {
  std::vector<double> coefficients;
  std::vector<double> row;
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
  float scale = 0;         // pulse S, Haar S₀
  float detail_scale = 0;  // Haar S_d
  std::size_t count = 0;
  std::span<const std::uint8_t> indices;  // count·W bytes, little-endian
  std::span<const std::uint8_t> values;   // count bytes: uint8, or int8 for Haar details
  std::size_t bytes = 1;                  // the whole record
};

// The record starting at bytes[0] (the span may run on into later records). InputError for an
// unknown kind, a bad scale or count, or a truncated record; indices are checked by the users
// below.
CubemapRecord parse_cubemap_record(int n, std::span<const std::uint8_t> bytes);

// Decodes the record at bytes[0] into 6·N² cell values; returns the record's size. scratch
// holds at least N values. InputError for an index out of range or not increasing.
std::size_t decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes,
                                    std::span<double> cells, std::span<double> scratch);
std::vector<double> decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes);

// The shell's radiance cubemap in both bases, rebuilt once per state change (paper §5:
// "cubemap representation and wavelet bases").
// The hot loop reads them as floats, one 16-byte texel a cell (issue 18: the window sum at the
// streaming rate; a double texel is 24 bytes and three separate multiply-adds).
struct alignas(16) ShellTexel {
  float rgb[4] = {0, 0, 0, 0};  // r, g, b, 0
};
struct ShellCubemap {
  int n = 0;
  std::vector<Rgb> cells;  // radiance per cell (pulse domain)
  std::vector<Rgb> haar;   // per face: orthonormal Haar coefficient k × S_k
  std::vector<ShellTexel> cells_float, haar_float;  // the same as floats
};
// Fills `shell` from 6·N² radiance cells, reusing its storage.
void prepare_shell_cubemap(int n, std::span<const Rgb> radiance, ShellCubemap& shell);
ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance);

// Σ_cells t̂·L for the record at bytes[0] (Eq. 7), as a sparse dot product in the record's
// basis, summed in float (the entries are 8-bit: float's 2⁻²⁴ is far below their 1/510).
// InputError for an index out of range.
Rgb dot_receiver_cubemap(std::span<const std::uint8_t> bytes, const ShellCubemap& shell);

// Bytes and basis split over a set of receivers.
struct CubemapEncodingStats {
  std::size_t receivers = 0, empty = 0, pulse = 0, haar = 0;
  std::size_t bytes = 0;                                // all records
  std::size_t pulse_bytes = 0, haar_bytes = 0;          // records of each kind
  std::size_t all_pulse_bytes = 0, all_haar_bytes = 0;  // had every receiver used one basis
                                                        // (add_receiver only; empty: 1 byte)
};
void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver);
// Walks a buffer of back-to-back records (all_*_bytes stay 0: the alternatives are unknown).
CubemapEncodingStats cubemap_encoding_stats(int n, std::span<const std::uint8_t> records);
double bytes_per_receiver(const CubemapEncodingStats& stats);

}  // namespace relight
