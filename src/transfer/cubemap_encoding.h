// Per-receiver compression of the direct portal component, as the interior-scene paper
// (papers/000_86ec1bd7f4a8db38 §3.4, §4.1.2, issue 4 item 3): each receiver's cubemap of
// light arriving through a portal (6·N² non-negative transfer weights t, one per cell, in the
// layout of math/cubemap.h, geometry only: the outgoing radiance is Σ_cells t·L_shell) is
// stored in whichever of two bases gives the smaller record, both quantised to 8 bits against
// the receiver's maximum ("we calculate the maximum contribution among all the directions for
// the vertex"):
//  * pulse functions: the non-zero cells, each (cell index, uint8 t/S·255). Best when the
//    portal covers few cells (a far or small window);
//  * per-face Haar wavelets (math/haar.h): the non-zero coefficients, each (index, int8).
//    Best when the portal covers a large smooth region (a receiver near a window).
// The run time (§5, Appendix Eq. 7) never decodes: it transforms the shell's radiance cubemap
// once per state change (ShellCubemap) and then each receiver is a sparse dot product: pulse
// Σ t_cell·L[cell]; Haar Σ T_k·H(L)_k, equal to the cell-domain dot product by Parseval (the
// transform is orthonormal).
//
// Haar quantisation. Coefficients are quantised in cell units: the amplitude of coefficient k
// is a_k = T_k / S_k, S_k = haar2d_support (the basis is ±1/S_k on S_k×S_k cells), i.e. the
// face mean for the scaling coefficient and a quarter of a signed sum of the four quadrant
// means for a detail; for t ≥ 0, |a_k| ≤ max t. Quantising a_k with one step for the receiver
// (rather than the orthonormal T_k, whose scaling coefficient is N × the mean) keeps the fine
// details, which carry the window's edges, as accurate as the coarse ones. The shell side folds
// S_k into its transformed radiance (ShellCubemap::haar), so the dot product is still one
// multiply-add per stored coefficient.
//
// Record byte layout (little-endian; records are stored back to back, no padding). W, the
// width of a cell or coefficient index and of the count, is 2 (uint16) when 6·N² ≤ 65535
// (N ≤ 64 for powers of two; the default N = 32) and 4 (uint32) otherwise:
//   byte 0       kind: 0 empty, 1 pulse, 2 Haar. An all-zero receiver is this one byte.
//   bytes 1..4   scale S, float32: for pulse S ≥ max t; for Haar S ≥ max |a_k|
//                (the float nearest above the double maximum, so quantised values never clip)
//   next W       count m of stored entries (1 ≤ m ≤ 6·N²)
//   next m·W     indices, strictly increasing: the cell index (face·N + row)·N + column,
//                the same for Haar coefficients (the coefficient (r, c) of face f is at
//                (f·N + r)·N + c, the Mallat layout of math/haar.h)
//   next m       values: pulse uint8 q, t = q·S/255; Haar int8 q ∈ [−127, 127],
//                a = q·S/127, T = a·S_k
// so a record is 1 byte (empty) or 1 + 4 + W + m·(W + 1) bytes: 7 + 3m for N ≤ 64.
//
// Error bounds (S the stored scale; τ the relative threshold, default 0):
//  * pulse, per cell: |t̂ − t| ≤ max(τ, 1/510)·S (rounding to the nearest of 256 levels;
//    cells that round to 0 or fall below τ·S are dropped).
//  * Haar, per coefficient amplitude: |â − a| ≤ max(τ, 1/254)·S (int8 rounding; drops alike);
//    per cell: |t̂ − t| ≤ (1 + 3·log2 N)·max(τ, 1/254)·S, since each cell lies under
//    1 + 3·log2 N basis functions, each of magnitude 1/S_k there (16/254·S ≈ 0.063·S at N =
//    32, a worst case: errors of independent coefficients mostly cancel).
//  * dot product with radiance L (each channel): pulse ≤ max(τ, 1/510)·S·Σ_{t>0} |L|;
//    Haar ≤ max(τ, 1/254)·S·Σ_k |S_k·H(L)_k| (ShellCubemap::haar), by Parseval.
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
  // Relative threshold τ: pulse drops cells t < τ·S, Haar drops coefficients |a| < τ·S. 0 keeps
  // everything that does not quantise to 0 (lossless up to the 8-bit quantisation).
  double threshold = 0.0;
  CubemapBasisChoice choice = CubemapBasisChoice::kSmaller;
};

// Bytes of an index or count in a record for face size N (2 or 4, see above).
constexpr std::size_t cubemap_code_index_bytes(int n) {
  return std::size_t{6} * n * n <= 65535 ? 2 : 4;
}
// Bytes of a record of m entries (m = 0: the 1-byte empty record).
constexpr std::size_t cubemap_record_bytes(int n, std::size_t entries) {
  return entries == 0 ? 1 : 1 + 4 + cubemap_code_index_bytes(n) * (entries + 1) + entries;
}

// What encoding one receiver wrote, and what each basis would have cost.
struct EncodedReceiver {
  CubemapCodeKind kind = CubemapCodeKind::kEmpty;
  std::size_t bytes = 0;        // appended to the buffer
  std::size_t pulse_bytes = 0;  // the pulse record's size
  std::size_t haar_bytes = 0;   // the Haar record's size
  float scale = 0;              // S of the record written (0 for empty)
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
  float scale = 0;
  std::size_t count = 0;
  std::span<const std::uint8_t> indices;  // count·W bytes, little-endian
  std::span<const std::uint8_t> values;   // count bytes: uint8 (pulse) or int8 (Haar)
  std::size_t bytes = 1;                  // the whole record
};

// The record starting at bytes[0] (the span may run on into later records). InputError for an
// unknown kind, a zero count or a truncated record; indices are checked by the users below.
CubemapRecord parse_cubemap_record(int n, std::span<const std::uint8_t> bytes);

// Decodes the record at bytes[0] into 6·N² cell values; returns the record's size. scratch
// holds at least N values. InputError for an index out of range or not increasing.
std::size_t decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes,
                                    std::span<double> cells, std::span<double> scratch);
std::vector<double> decode_receiver_cubemap(int n, std::span<const std::uint8_t> bytes);

// The shell's radiance cubemap in both bases, rebuilt once per state change (paper §5:
// "cubemap representation and wavelet bases").
struct ShellCubemap {
  int n = 0;
  std::vector<Rgb> cells;  // radiance per cell (pulse domain)
  std::vector<Rgb> haar;   // per face: orthonormal Haar coefficient k × S_k
};
// Fills `shell` from 6·N² radiance cells, reusing its storage.
void prepare_shell_cubemap(int n, std::span<const Rgb> radiance, ShellCubemap& shell);
ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance);

// Σ_cells t̂·L for the record at bytes[0] (Eq. 7), as a sparse dot product in the record's
// basis. InputError for an index out of range.
Rgb dot_receiver_cubemap(std::span<const std::uint8_t> bytes, const ShellCubemap& shell);

// Bytes and basis split over a set of receivers.
struct CubemapEncodingStats {
  std::size_t receivers = 0, empty = 0, pulse = 0, haar = 0;
  std::size_t bytes = 0;                            // all records
  std::size_t pulse_bytes = 0, haar_bytes = 0;      // records of each kind
  std::size_t all_pulse_bytes = 0, all_haar_bytes = 0;  // had every receiver used one basis
                                                        // (add_receiver only; empty: 1 byte)
};
void add_receiver(CubemapEncodingStats& stats, const EncodedReceiver& receiver);
// Walks a buffer of back-to-back records (all_*_bytes stay 0: the alternatives are unknown).
CubemapEncodingStats cubemap_encoding_stats(int n, std::span<const std::uint8_t> records);
double bytes_per_receiver(const CubemapEncodingStats& stats);

}  // namespace relight
