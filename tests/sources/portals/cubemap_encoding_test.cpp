// Per-receiver pulse / pulse-run / face-rectangle / Haar encoding of the direct portal cubemap
// (sources/portals/cubemap_encoding.h, Yue et al. 2009 §4.1.2): round trips within the stated 8-bit
// bounds, the run-time sparse dot product against the dense one and against the unquantised vector,
// the record chooser, the byte counts, and the sizes measured on sample receivers (a far window, a
// near window, an open sky).
#include "sources/portals/cubemap_encoding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/input_error.h"
#include "math/cubemap.h"
#include "math/haar.h"
#include "math/sampling.h"

namespace relight {
namespace {

// Transfer weights of a diffuse receiver at the origin, normal +y, for light through a window
// in the wall z = −d spanning x ∈ [−w/2, w/2], y ∈ [y0, y1]: cosθ·Ω/π per cell whose centre
// direction passes through it (irradiance per unit radiance, albedo 1).
std::vector<double> window_cubemap(int n, double d, double w, double y0, double y1) {
  std::vector<double> t(cubemap_texel_count(n), 0.0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const CubemapTexel tx = cubemap_texel_from_index(n, k);
    const Vec3 dir = cubemap_texel_direction(n, tx);
    if (dir.z >= 0 || dir.y <= 0) continue;
    const double s = -d / dir.z, x = s * dir.x, y = s * dir.y;
    if (std::abs(x) <= 0.5 * w && y >= y0 && y <= y1)
      t[k] = dir.y * cubemap_texel_solid_angle(n, tx.i, tx.j) / kPi;
  }
  return t;
}

// The same receiver under an open sky: the whole upper hemisphere, smooth, non-zero on half
// the cells.
std::vector<double> sky_cubemap(int n) {
  std::vector<double> t(cubemap_texel_count(n), 0.0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const CubemapTexel tx = cubemap_texel_from_index(n, k);
    const Vec3 dir = cubemap_texel_direction(n, tx);
    if (dir.y > 0) t[k] = dir.y * cubemap_texel_solid_angle(n, tx.i, tx.j) / kPi;
  }
  return t;
}

// A few random non-zero cells, plus two tiny ones that quantise to zero.
std::vector<double> sparse_cubemap(int n, int cells, Pcg32& rng) {
  std::vector<double> t(cubemap_texel_count(n), 0.0);
  for (int c = 0; c < cells; ++c) t[rng.next_u32() % t.size()] = 0.1 + rng.next_double();
  t[3] = t[4] = 1e-5;
  return t;
}

std::vector<Rgb> random_radiance(int n, Pcg32& rng) {
  std::vector<Rgb> l(cubemap_texel_count(n));
  for (Rgb& c : l) c = {rng.next_double(), 2 * rng.next_double(), 0.5 * rng.next_double()};
  return l;
}

Rgb dense_dot(const std::vector<double>& t, const std::vector<Rgb>& l) {
  Rgb s;
  for (std::size_t k = 0; k < t.size(); ++k) s += l[k] * t[k];
  return s;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(a[k] - b[k]));
  return m;
}

double max_value(const std::vector<double>& a) {
  return *std::max_element(a.begin(), a.end());
}

// Per-face Haar amplitudes a_k = T_k / S_k (the quantity the Haar record stores).
std::vector<double> amplitudes(int n, std::vector<double> cells) {
  std::vector<double> scratch(n);
  haar2d_forward_faces(cells, n, scratch);
  const std::size_t nn = std::size_t(n) * n;
  for (std::size_t k = 0; k < cells.size(); ++k)
    cells[k] /= haar2d_support(n, static_cast<int>(k % nn / n), static_cast<int>(k % n));
  return cells;
}

EncodedReceiver encode(int n, const std::vector<double>& t, std::vector<std::uint8_t>& out,
                       CubemapBasisChoice choice = CubemapBasisChoice::kSmaller,
                       double threshold = 0.0) {
  CubemapEncodeOptions options;
  options.choice = choice;
  options.threshold = threshold;
  return encode_receiver_cubemap(n, t, options, out);
}

const char* kind_name(CubemapCodeKind kind) {
  switch (kind) {
    case CubemapCodeKind::kEmpty:
      return "empty";
    case CubemapCodeKind::kPulse:
      return "pulse";
    case CubemapCodeKind::kHaar:
      return "haar";
    case CubemapCodeKind::kRuns:
      return "runs";
    case CubemapCodeKind::kRectangles:
      return "rectangles";
  }
  return "?";
}

TEST(CubemapEncoding, AllZeroReceiverIsTheOneByteEmptyRecord) {
  const int n = 32;
  std::vector<std::uint8_t> out;
  const EncodedReceiver r = encode(n, std::vector<double>(cubemap_texel_count(n), 0.0), out);
  EXPECT_EQ(r.kind, CubemapCodeKind::kEmpty);
  EXPECT_EQ(r.bytes, 1u);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(parse_cubemap_record(n, out).bytes, 1u);
  const std::vector<double> d = decode_receiver_cubemap(n, out);
  EXPECT_EQ(max_value(d), 0.0);
  Pcg32 rng(1, 1);
  const ShellCubemap shell = prepare_shell_cubemap(n, random_radiance(n, rng));
  const Rgb v = dot_receiver_cubemap(out, shell);
  EXPECT_EQ(v.r + v.g + v.b, 0.0);
}

// Pulse: |t̂ − t| ≤ S/510 per cell (nearest of 256 levels), S the stored float scale, which is
// the receiver maximum rounded up to a float.
TEST(CubemapEncoding, PulseRoundTripWithinHalfQuantisationStep) {
  const int n = 32;
  Pcg32 rng(7, 8);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> t = sparse_cubemap(n, 12, rng);
    std::vector<std::uint8_t> out;
    const EncodedReceiver r = encode(n, t, out);
    ASSERT_EQ(r.kind, CubemapCodeKind::kPulse);
    const double vmax = max_value(t);
    EXPECT_GE(r.scale, vmax);
    EXPECT_LE(r.scale, vmax * (1 + 1.2e-7));
    const std::vector<double> d = decode_receiver_cubemap(n, out);
    EXPECT_LE(max_abs_diff(d, t), r.scale / 510.0 * (1 + 1e-12));
    // the two 1e-5 cells quantise to 0 and are not stored: 12 or fewer entries
    EXPECT_LE(parse_cubemap_record(n, out).count, 12u);
  }
}

// Largest amplitude errors of a decoded Haar receiver: {face means, details}.
std::pair<double, double> amplitude_errors(int n, const std::vector<double>& decoded,
                                           const std::vector<double>& original) {
  const std::vector<double> a = amplitudes(n, original), d = amplitudes(n, decoded);
  const std::size_t nn = std::size_t(n) * n;
  double mean = 0, detail = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    (k % nn == 0 ? mean : detail) = std::max(k % nn == 0 ? mean : detail, std::abs(a[k] - d[k]));
  return {mean, detail};
}

// Haar: face means within S₀/510 (uint8), details within S_d/254 (int8), hence each cell
// within S₀/510 + 3·log2 N·S_d/254; also for dense random data forced into Haar (a worst case).
TEST(CubemapEncoding, HaarRoundTripWithinDerivedBound) {
  const int n = 32, levels = 5;
  Pcg32 rng(9, 10);
  std::vector<double> noise(cubemap_texel_count(n));
  for (double& v : noise) v = rng.next_double();
  const std::vector<std::vector<double>> inputs = {
      sky_cubemap(n), window_cubemap(n, 1.0, 2.0, 0.5, 2.5), noise, sparse_cubemap(n, 20, rng)};
  for (const std::vector<double>& t : inputs) {
    std::vector<std::uint8_t> out;
    const EncodedReceiver r = encode(n, t, out, CubemapBasisChoice::kHaar);
    ASSERT_EQ(r.kind, CubemapCodeKind::kHaar);
    const std::vector<double> a = amplitudes(n, t);
    double mean_max = 0.0, detail_max = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
      (k % (n * n) == 0 ? mean_max : detail_max) =
          std::max(k % (n * n) == 0 ? mean_max : detail_max, std::abs(a[k]));
    const double tmax = max_value(t);
    EXPECT_GE(r.scale, mean_max);
    EXPECT_GE(r.detail_scale, detail_max);
    EXPECT_LE(r.scale, tmax * (1 + 1.2e-7));             // mean ≤ max t
    EXPECT_LE(r.detail_scale, tmax / 2 * (1 + 1.2e-7));  // |detail| ≤ max t / 2
    const std::vector<double> d = decode_receiver_cubemap(n, out);
    const auto [mean_err, detail_err] = amplitude_errors(n, d, t);
    EXPECT_LE(mean_err, r.scale / 510.0 * (1 + 1e-9));
    EXPECT_LE(detail_err, r.detail_scale / 254.0 * (1 + 1e-9));
    const double bound = r.scale / 510.0 + 3 * levels * r.detail_scale / 254.0;
    const double cell_err = max_abs_diff(d, t);
    EXPECT_LE(cell_err, bound);
    EXPECT_LE(bound, (1 / 510.0 + 3 * levels / 508.0) * tmax * (1 + 1e-6));
    // Details sum to 0 over a face, so a face's Σ t̂ errs by N² × its mean's error only.
    for (int f = 0; f < 6; ++f) {
      double sum = 0, dsum = 0;
      for (int k = f * n * n; k < (f + 1) * n * n; ++k) {
        sum += t[k];
        dsum += d[k];
      }
      EXPECT_LE(std::abs(dsum - sum), n * n * r.scale / 510.0 * (1 + 1e-9) + 1e-12 * sum) << f;
    }
    std::printf("[haar] max cell error %.3g = %.3g of max t (bound %.3g)\n", cell_err,
                cell_err / tmax, bound / tmax);
  }
}

TEST(CubemapEncoding, SparseDotEqualsDenseDotOfDecodedTo1e6) {
  const int n = 32;
  Pcg32 rng(11, 12);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  const std::vector<std::vector<double>> inputs = {sparse_cubemap(n, 20, rng), sky_cubemap(n),
                                                   window_cubemap(n, 1.0, 2.0, 0.5, 2.5)};
  for (const auto& t : inputs)
    for (CubemapBasisChoice choice : {CubemapBasisChoice::kPulse, CubemapBasisChoice::kHaar,
                                      CubemapBasisChoice::kRuns, CubemapBasisChoice::kRectangles}) {
      std::vector<std::uint8_t> out;
      encode(n, t, out, choice);
      const Rgb sparse = dot_receiver_cubemap(out, shell);
      const Rgb dense = dense_dot(decode_receiver_cubemap(n, out), l);
      EXPECT_NEAR(sparse.r / dense.r, 1.0, 1e-6);
      EXPECT_NEAR(sparse.g / dense.g, 1.0, 1e-6);
      EXPECT_NEAR(sparse.b / dense.b, 1.0, 1e-6);
    }
}

// The pulse sum's fast loop (two entries a step, the last 0-7 apart; indices checked sixteen at
// a time, the last sixteen overlapping) against the decoded record's dense dot, for every entry
// count from 1 to 70; and an index out of range anywhere in a record is an InputError before
// the shell is read.
TEST(CubemapEncoding, PulseDotOfEveryLengthEqualsDenseDotTo1e6AndChecksEveryIndex) {
  const int n = 32;
  Pcg32 rng(31, 32);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  for (int m = 1; m <= 70; ++m) {
    std::vector<double> t(cubemap_texel_count(n), 0.0);
    for (int placed = 0; placed < m;) {
      double& cell = t[rng.next_u32() % t.size()];
      if (cell > 0) continue;
      cell = 0.1 + rng.next_double();
      ++placed;
    }
    std::vector<std::uint8_t> out;
    ASSERT_EQ(encode(n, t, out, CubemapBasisChoice::kPulse).kind, CubemapCodeKind::kPulse);
    ASSERT_EQ(parse_cubemap_record(n, out).count, static_cast<std::size_t>(m));
    const Rgb sparse = dot_receiver_cubemap(out, shell);
    const Rgb dense = dense_dot(decode_receiver_cubemap(n, out), l);
    EXPECT_NEAR(sparse.r / dense.r, 1.0, 1e-6) << m;
    EXPECT_NEAR(sparse.g / dense.g, 1.0, 1e-6) << m;
    EXPECT_NEAR(sparse.b / dense.b, 1.0, 1e-6) << m;
    for (const int e : {0, m / 2, m - 1}) {
      std::vector<std::uint8_t> bad = out;
      const std::size_t at = 1 + 4 + 2 + 2 * static_cast<std::size_t>(e);  // kind, S, count
      bad[at] = 0xff;
      bad[at + 1] = 0xff;  // 65535 ≥ 6·32²
      EXPECT_THROW(dot_receiver_cubemap(bad, shell), InputError) << m << " " << e;
    }
  }
}

// Runs: each cell within S/510 as pulse; a gap of up to 2W = 4 cells joins two runs (stored
// as zero levels), a gap of five starts a new run.
TEST(CubemapEncoding, RunsRoundTripWithinHalfQuantisationStepAndJoinGapsOfFourCells) {
  const int n = 32;
  const std::vector<double> t = window_cubemap(n, 3.0, 1.0, 1.0, 2.0);
  std::vector<std::uint8_t> out;
  const EncodedReceiver r = encode(n, t, out, CubemapBasisChoice::kRuns);
  ASSERT_EQ(r.kind, CubemapCodeKind::kRuns);
  EXPECT_GE(r.scale, max_value(t));
  EXPECT_LE(max_abs_diff(decode_receiver_cubemap(n, out), t), r.scale / 510.0 * (1 + 1e-12));
  for (const auto& [gap, runs] : {std::pair{4, 1u}, std::pair{5, 2u}}) {
    std::vector<double> two(cubemap_texel_count(n), 0.0);
    two[100] = 1.0;
    two[101 + gap] = 0.6;  // 153/255: both levels exact
    out.clear();
    encode(n, two, out, CubemapBasisChoice::kRuns);
    const CubemapRecord rec = parse_cubemap_record(n, out);
    EXPECT_EQ(rec.runs, runs) << gap;
    EXPECT_EQ(rec.count, runs == 1 ? 2u + gap : 2u) << gap;
    EXPECT_LE(max_abs_diff(decode_receiver_cubemap(n, out), two), 1e-15) << gap;
  }
}

// The runs' sum (eight cells a step, a run's last 1-7 read as the bytes that end them; whole
// eights and the rest in separate sums) against the decoded record's dense dot, for runs of
// every length from 1 to 40 at every offset in eight, one to three runs, the last ending at the
// cubemap's last cell (the planes' padding read); and a run record whose runs leave the
// cubemap, overlap, are empty or do not hold the levels is an InputError.
TEST(CubemapEncoding, RunDotOfEveryLengthAndGapEqualsDenseDotTo1e6AndChecksEveryRun) {
  const int n = 32;
  const std::size_t cells = cubemap_texel_count(n);
  Pcg32 rng(33, 34);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  for (std::size_t length = 1; length <= 40; ++length)
    for (std::size_t runs = 1; runs <= 3; ++runs) {
      std::vector<double> t(cells, 0.0);
      for (std::size_t j = 0; j < runs; ++j) {
        const std::size_t end = cells - j * (length + 13) - (length + j) % 8;  // gaps ≥ 6
        for (std::size_t k = end - length; k < end; ++k) t[k] = 0.1 + rng.next_double();
      }
      std::vector<std::uint8_t> out;
      ASSERT_EQ(encode(n, t, out, CubemapBasisChoice::kRuns).kind, CubemapCodeKind::kRuns);
      const CubemapRecord rec = parse_cubemap_record(n, out);
      ASSERT_EQ(rec.runs, runs);
      ASSERT_EQ(rec.count, runs * length);
      const Rgb sparse = dot_receiver_cubemap(out, shell);
      const Rgb dense = dense_dot(decode_receiver_cubemap(n, out), l);
      EXPECT_NEAR(sparse.r / dense.r, 1.0, 1e-6) << length << " " << runs;
      EXPECT_NEAR(sparse.g / dense.g, 1.0, 1e-6) << length << " " << runs;
      EXPECT_NEAR(sparse.b / dense.b, 1.0, 1e-6) << length << " " << runs;
      // A run's start and length are at 9 + 4j and 11 + 4j (kind, S, run count, level count).
      const auto set16 = [](std::vector<std::uint8_t>& bytes, std::size_t at, std::size_t v) {
        bytes[at] = static_cast<std::uint8_t>(v & 0xff);
        bytes[at + 1] = static_cast<std::uint8_t>(v >> 8);
      };
      const std::size_t last = 9 + 4 * (runs - 1);
      std::vector<std::vector<std::uint8_t>> bad(4, out);
      set16(bad[0], last, cells - length + 1);  // the last run leaves the cubemap
      set16(bad[1], last + 2, 0);               // an empty run
      set16(bad[2], last + 2, length + 1);      // more than the levels
      set16(bad[3], 9, cells);                  // the first run starts beyond the cubemap
      if (length > 1) bad.push_back(out), set16(bad.back(), last + 2, length - 1);  // fewer
      if (runs > 1) bad.push_back(out), set16(bad.back(), 13, 0);  // before the first's end
      for (std::size_t b = 0; b < bad.size(); ++b) {
        EXPECT_THROW(dot_receiver_cubemap(bad[b], shell), InputError) << length << " " << b;
        EXPECT_THROW(decode_receiver_cubemap(n, bad[b]), InputError) << length << " " << b;
      }
    }
}

// The rectangles' sum (a row eight cells at a time, its last 1-7 read as the bytes that end it)
// against the decoded record's dense dot, for rectangles of every width from 1 to N at offsets
// that make every remainder, one to three rows, on one to three faces, the last one ending at
// the cubemap's last cell (the planes' padding read); and a rectangle record whose rectangles
// leave their face, repeat or reorder faces, number 0 or 7, or lack levels is an InputError.
TEST(CubemapEncoding, RectangleDotOfEveryWidthAndPlaceEqualsDenseDotTo1e6AndChecksEveryRectangle) {
  const int n = 32;
  Pcg32 rng(37, 38);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  for (int width = 1; width <= n; ++width)
    for (int height = 1; height <= 3; ++height)
      for (std::size_t faces = 1; faces <= 3; ++faces) {
        std::vector<double> t(cubemap_texel_count(n), 0.0);
        for (std::size_t f = 0; f < faces; ++f) {
          const std::size_t face = 5 - 2 * f;
          const int x0 = f == 0 ? n - width : (width + height) % (n - width + 1);
          const int y0 = f == 0 ? n - height : static_cast<int>(f);
          for (int y = y0; y < y0 + height; ++y)
            for (int x = x0; x < x0 + width; ++x)
              t[face * nn + static_cast<std::size_t>(y) * n + x] = 0.1 + rng.next_double();
        }
        std::vector<std::uint8_t> out;
        ASSERT_EQ(encode(n, t, out, CubemapBasisChoice::kRectangles).kind,
                  CubemapCodeKind::kRectangles);
        const CubemapRecord rec = parse_cubemap_record(n, out);
        ASSERT_EQ(rec.rectangles, faces);
        ASSERT_EQ(rec.count, faces * static_cast<std::size_t>(width * height));
        EXPECT_LE(max_abs_diff(decode_receiver_cubemap(n, out), t),
                  rec.scale / 510.0 * (1 + 1e-12));
        const Rgb sparse = dot_receiver_cubemap(out, shell);
        const Rgb dense = dense_dot(decode_receiver_cubemap(n, out), l);
        EXPECT_NEAR(sparse.r / dense.r, 1.0, 1e-6) << width << " " << height << " " << faces;
        EXPECT_NEAR(sparse.g / dense.g, 1.0, 1e-6) << width << " " << height << " " << faces;
        EXPECT_NEAR(sparse.b / dense.b, 1.0, 1e-6) << width << " " << height << " " << faces;
        // Rectangle j's face, x0, y0, w − 1, h − 1 are bytes 6 + 5j … 10 + 5j, faces increasing.
        const std::size_t first = 6;
        std::vector<std::vector<std::uint8_t>> bad(5, out);
        bad[0][first + 1] = static_cast<std::uint8_t>(n - width + 1);   // leaves its face's rows
        bad[1][first + 2] = static_cast<std::uint8_t>(n - height + 1);  // leaves its face
        bad[2][first] = 6;                                              // no seventh face
        bad[3][5] = 0;                                                  // no rectangles
        bad[4][5] = 7;
        bad.push_back(std::vector<std::uint8_t>(out.begin(), out.end() - 1));  // a level short
        if (faces > 1) bad.push_back(out), bad.back()[first + 5] = bad.back()[first];  // repeated
        for (std::size_t b = 0; b < bad.size(); ++b) {
          EXPECT_THROW(dot_receiver_cubemap(bad[b], shell), InputError) << width << " " << b;
          EXPECT_THROW(decode_receiver_cubemap(n, bad[b]), InputError) << width << " " << b;
        }
      }
}

// A block's records summed in one call (the run and rectangle records parsed inline) add what
// dot_receiver_cubemap gives each, to float rounding (4 ulps: the add may fuse with the
// scale's multiply), whatever the kinds around them, and the same floats whatever bytes it is
// given to prefetch (none, fewer lines than records, more); offsets out of order or
// beyond the records, and a malformed run or rectangle record, are InputErrors.
TEST(CubemapEncoding, BlockOfRecordsAddsEachRecordsDotExactly) {
  const int n = 32;
  Pcg32 rng(35, 36);
  const ShellCubemap shell = prepare_shell_cubemap(n, random_radiance(n, rng));
  std::vector<std::uint8_t> records;
  std::vector<std::uint64_t> offsets = {0};
  const std::vector<std::vector<double>> inputs = {
      window_cubemap(n, 2.0, 1.0, 1.0, 2.0), sparse_cubemap(n, 12, rng),
      std::vector<double>(cubemap_texel_count(n), 0.0), window_cubemap(n, 1.0, 2.0, 0.5, 2.5),
      sky_cubemap(n)};
  for (const auto& t : inputs)
    for (CubemapBasisChoice choice : {CubemapBasisChoice::kSmaller, CubemapBasisChoice::kRuns,
                                      CubemapBasisChoice::kHaar, CubemapBasisChoice::kRectangles}) {
      encode(n, t, records, choice);
      offsets.push_back(records.size());
    }
  const std::size_t count = offsets.size() - 1;
  std::vector<float> red(count, 1.0f), green(count, 2.0f), blue(count, 3.0f);
  add_receiver_cubemaps(records, offsets, shell, red, green, blue);
  for (std::size_t i = 0; i < count; ++i) {
    const Rgb e = dot_receiver_cubemap(
        std::span(records).subspan(offsets[i], offsets[i + 1] - offsets[i]), shell);
    EXPECT_FLOAT_EQ(red[i], 1.0f + static_cast<float>(e.r)) << i;
    EXPECT_FLOAT_EQ(green[i], 2.0f + static_cast<float>(e.g)) << i;
    EXPECT_FLOAT_EQ(blue[i], 3.0f + static_cast<float>(e.b)) << i;
  }
  for (const std::size_t bytes :
       {std::size_t{1}, std::size_t{100}, 64 * count + 3, std::size_t{64000}}) {
    const std::vector<std::byte> next(bytes);
    std::vector<float> r(count, 1.0f), g(count, 2.0f), b(count, 3.0f);
    add_receiver_cubemaps(records, offsets, shell, r, g, b, next);
    EXPECT_EQ(r, red) << bytes;
    EXPECT_EQ(g, green) << bytes;
    EXPECT_EQ(b, blue) << bytes;
  }
  std::vector<std::uint64_t> bad = offsets;
  bad[3] = bad[2];
  EXPECT_THROW(add_receiver_cubemaps(records, bad, shell, red, green, blue), InputError);
  bad = offsets;
  bad.back() = records.size() + 1;
  EXPECT_THROW(add_receiver_cubemaps(records, bad, shell, red, green, blue), InputError);
  std::vector<std::uint8_t> broken = records;
  ASSERT_EQ(broken[offsets[1]], static_cast<std::uint8_t>(CubemapCodeKind::kRuns));
  broken[offsets[1] + 7] = 0xff;  // a level count beyond the record
  EXPECT_THROW(add_receiver_cubemaps(broken, offsets, shell, red, green, blue), InputError);
  broken = records;
  ASSERT_EQ(broken[offsets[3]], static_cast<std::uint8_t>(CubemapCodeKind::kRectangles));
  broken[offsets[3] + 6 + 3] = 0xff;  // the first rectangle 256 cells wide
  EXPECT_THROW(add_receiver_cubemaps(broken, offsets, shell, red, green, blue), InputError);
  EXPECT_THROW(
      add_receiver_cubemaps(records, offsets, shell, std::span(red).first(count - 1), green, blue),
      std::invalid_argument);
}

// Against the unquantised vector: pulse |Σ(t̂ − t)L| ≤ S/510·Σ_{t>0}|L|; Haar ≤ S/254·Σ_k|S_k
// H(L)_k| (Parseval), per channel.
TEST(CubemapEncoding, DotWithinQuantisationBoundOfOriginal) {
  const int n = 32;
  Pcg32 rng(13, 14);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  const std::vector<std::vector<double>> inputs = {sparse_cubemap(n, 20, rng), sky_cubemap(n),
                                                   window_cubemap(n, 1.0, 2.0, 0.5, 2.5)};
  for (const auto& t : inputs)
    for (CubemapBasisChoice choice : {CubemapBasisChoice::kPulse, CubemapBasisChoice::kHaar,
                                      CubemapBasisChoice::kRuns, CubemapBasisChoice::kRectangles}) {
      std::vector<std::uint8_t> out;
      const EncodedReceiver r = encode(n, t, out, choice);
      const Rgb got = dot_receiver_cubemap(out, shell), exact = dense_dot(t, l);
      Rgb bound;
      if (r.kind != CubemapCodeKind::kHaar) {
        for (std::size_t k = 0; k < t.size(); ++k)
          if (t[k] > 0) bound += l[k];
        bound *= r.scale / 510.0;
      } else {
        for (std::size_t k = 0; k < t.size(); ++k) {
          const Rgb& h = shell.haar[k];
          const double e = k % (n * n) == 0 ? r.scale / 510.0 : r.detail_scale / 254.0;
          bound += Rgb{std::abs(h.r), std::abs(h.g), std::abs(h.b)} * e;
        }
      }
      EXPECT_LE(std::abs(got.r - exact.r), bound.r);
      EXPECT_LE(std::abs(got.g - exact.g), bound.g);
      EXPECT_LE(std::abs(got.b - exact.b), bound.b);
      const double rel = std::abs(got.g / exact.g - 1.0);
      std::printf("[dot] %s %s relative error %.2e\n", kind_name(r.kind),
                  &t == &inputs[0]   ? "sparse"
                  : &t == &inputs[1] ? "sky"
                                     : "window",
                  rel);
    }
}

// The smallest record wins: scattered cells as pulse functions, a window's patch as rectangles
// (under the runs, about half the pulse record), a diagonal line of cells as runs (its
// rectangle is mostly zero levels), a cubemap constant on each face as Haar (six face means).
TEST(CubemapEncoding, ChooserPicksPulseForScatteredCellsRectanglesForAWindowAndHaarForFlatFaces) {
  const int n = 32;
  Pcg32 rng(15, 16);
  std::vector<std::uint8_t> out;
  const EncodedReceiver few = encode(n, sparse_cubemap(n, 10, rng), out);
  EXPECT_EQ(few.kind, CubemapCodeKind::kPulse);
  EXPECT_LT(few.pulse_bytes, few.runs_bytes);
  EXPECT_LT(few.pulse_bytes, few.rectangles_bytes);
  EXPECT_LT(few.pulse_bytes, few.haar_bytes);
  EXPECT_LE(few.bytes, cubemap_record_bytes(n, CubemapCodeKind::kPulse, 10));
  const EncodedReceiver window = encode(n, window_cubemap(n, 2.0, 1.0, 1.0, 2.0), out);
  EXPECT_EQ(window.kind, CubemapCodeKind::kRectangles);
  EXPECT_LT(window.rectangles_bytes, window.runs_bytes);
  EXPECT_LT(window.runs_bytes, 0.6 * static_cast<double>(window.pulse_bytes));  // 105 of 199 B
  EXPECT_LT(window.runs_bytes, window.haar_bytes);
  std::vector<double> diagonal(cubemap_texel_count(n), 0.0);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 3; ++j) diagonal[static_cast<std::size_t>(4 * i * (n + 1) + j)] = 1.0;
  const EncodedReceiver line = encode(n, diagonal, out);
  EXPECT_EQ(line.kind, CubemapCodeKind::kRuns);  // 8 runs of 3: 65 B; a 31 × 29 rectangle
  EXPECT_EQ(line.bytes, cubemap_record_bytes(n, CubemapCodeKind::kRuns, 24, 8));
  EXPECT_EQ(line.rectangles_bytes,
            cubemap_record_bytes(n, CubemapCodeKind::kRectangles, 31 * 29, 1));
  std::vector<double> flat(cubemap_texel_count(n));
  for (std::size_t k = 0; k < flat.size(); ++k) flat[k] = 1.0 + static_cast<double>(k / (n * n));
  const EncodedReceiver faces = encode(n, flat, out);
  EXPECT_EQ(faces.kind, CubemapCodeKind::kHaar);
  EXPECT_EQ(faces.bytes, cubemap_record_bytes(n, CubemapCodeKind::kHaar, 6));
  EXPECT_EQ(faces.pulse_bytes, cubemap_record_bytes(n, CubemapCodeKind::kPulse, flat.size()));
  EXPECT_EQ(faces.runs_bytes, cubemap_record_bytes(n, CubemapCodeKind::kRuns, flat.size(), 1));
  EXPECT_EQ(faces.rectangles_bytes,
            cubemap_record_bytes(n, CubemapCodeKind::kRectangles, flat.size(), 6));
}

TEST(CubemapEncoding, BytesCountedMatchTheBufferAndStats) {
  const int n = 16;
  Pcg32 rng(17, 18);
  std::vector<std::uint8_t> buffer;
  CubemapEncodingStats added;
  std::vector<std::vector<double>> inputs = {
      sparse_cubemap(n, 5, rng), sky_cubemap(n), std::vector<double>(cubemap_texel_count(n), 0.0),
      window_cubemap(n, 6.0, 1.0, 1.0, 2.0), window_cubemap(n, 0.5, 2.0, 0.2, 2.0)};
  CubemapEncodeScratch scratch;
  for (const auto& t : inputs) {
    const std::size_t before = buffer.size();
    const EncodedReceiver r = encode_receiver_cubemap(n, t, {}, buffer, scratch);
    std::printf("[bytes] %s %zu B (pulse %zu, runs %zu, rectangles %zu, haar %zu)\n",
                kind_name(r.kind), r.bytes, r.pulse_bytes, r.runs_bytes, r.rectangles_bytes,
                r.haar_bytes);
    EXPECT_EQ(r.bytes, buffer.size() - before);
    EXPECT_EQ(r.bytes, std::min({r.pulse_bytes, r.haar_bytes, r.runs_bytes, r.rectangles_bytes}));
    const CubemapRecord rec = parse_cubemap_record(n, std::span(buffer).subspan(before));
    EXPECT_EQ(rec.bytes, r.bytes);
    EXPECT_EQ(rec.bytes,
              cubemap_record_bytes(n, rec.kind, rec.count,
                                   rec.kind == CubemapCodeKind::kRuns ? rec.runs : rec.rectangles));
    if (rec.kind == CubemapCodeKind::kPulse) {
      EXPECT_EQ(rec.bytes, 7 + 3 * rec.count);
    } else if (rec.kind == CubemapCodeKind::kHaar) {
      EXPECT_EQ(rec.bytes, 11 + 3 * rec.count);
    } else if (rec.kind == CubemapCodeKind::kRuns) {
      EXPECT_EQ(rec.bytes, 9 + 4 * rec.runs + rec.count);
    } else if (rec.kind == CubemapCodeKind::kRectangles) {
      EXPECT_EQ(rec.bytes, 6 + 5 * rec.rectangles + rec.count);
    }
    add_receiver(added, r);
  }
  const CubemapEncodingStats walked = cubemap_encoding_stats(n, buffer);
  EXPECT_EQ(walked.receivers, 5u);
  EXPECT_EQ(walked.bytes, buffer.size());
  EXPECT_EQ(added.bytes, buffer.size());
  EXPECT_EQ(walked.empty, 1u);
  EXPECT_EQ(walked.pulse, added.pulse);
  EXPECT_EQ(walked.haar, added.haar);
  EXPECT_EQ(walked.runs, added.runs);
  EXPECT_EQ(walked.rectangles, added.rectangles);
  EXPECT_EQ(walked.pulse, 1u);       // the scattered cells
  EXPECT_EQ(walked.runs, 1u);        // the sky (two bytes under its rectangles)
  EXPECT_EQ(walked.rectangles, 2u);  // the far window's four cells and the near window
  EXPECT_EQ(walked.pulse + walked.haar + walked.runs + walked.rectangles + walked.empty, 5u);
  EXPECT_EQ(
      walked.pulse_bytes + walked.haar_bytes + walked.runs_bytes + walked.rectangles_bytes + 1,
      buffer.size());
  EXPECT_EQ(walked.pulse_bytes, added.pulse_bytes);
  EXPECT_EQ(walked.runs_bytes, added.runs_bytes);
  EXPECT_EQ(walked.rectangles_bytes, added.rectangles_bytes);
  EXPECT_GE(added.all_pulse_bytes, added.bytes);
  EXPECT_GE(added.all_haar_bytes, added.bytes);
  EXPECT_GE(added.all_runs_bytes, added.bytes);
  EXPECT_GE(added.all_rectangles_bytes, added.bytes);
  CubemapEncodingStats twice = added;
  add_stats(twice, added);
  EXPECT_EQ(twice.runs_bytes, 2 * added.runs_bytes);
  EXPECT_EQ(twice.rectangles, 2 * added.rectangles);
  EXPECT_EQ(twice.all_rectangles_bytes, 2 * added.all_rectangles_bytes);
  EXPECT_EQ(twice.all_haar_bytes, 2 * added.all_haar_bytes);
  EXPECT_EQ(twice.receivers, 10u);
  EXPECT_DOUBLE_EQ(bytes_per_receiver(walked), buffer.size() / 5.0);
}

TEST(CubemapEncoding, ThresholdDropsCoefficientsWithinItsBound) {
  const int n = 32;
  const std::vector<double> t = window_cubemap(n, 1.0, 2.0, 0.5, 2.5);
  std::size_t previous = t.size() + 1;
  for (double tau : {0.0, 0.01, 0.05}) {
    std::vector<std::uint8_t> out;
    const EncodedReceiver r = encode(n, t, out, CubemapBasisChoice::kHaar, tau);
    const std::size_t count = parse_cubemap_record(n, out).count;
    EXPECT_LT(count, previous) << tau;
    previous = count;
    const std::vector<double> d = decode_receiver_cubemap(n, out);
    const auto [mean_err, detail_err] = amplitude_errors(n, d, t);
    EXPECT_LE(mean_err, std::max(tau, 1 / 510.0) * r.scale * (1 + 1e-9)) << tau;
    EXPECT_LE(detail_err, std::max(tau, 1 / 254.0) * r.detail_scale * (1 + 1e-9)) << tau;
  }
}

// 6·N² > 65535: indices and count take 4 bytes, a record 9 + 5m.
TEST(CubemapEncoding, WideIndicesForLargeFaces) {
  const int n = 128;
  EXPECT_EQ(cubemap_code_index_bytes(32), 2u);
  EXPECT_EQ(cubemap_code_index_bytes(64), 2u);
  EXPECT_EQ(cubemap_code_index_bytes(n), 4u);
  std::vector<double> t(cubemap_texel_count(n), 0.0);
  t[70000] = 2.0;
  t[98303] = 1.0;
  std::vector<std::uint8_t> out;
  const EncodedReceiver r = encode(n, t, out, CubemapBasisChoice::kPulse);
  EXPECT_EQ(r.kind, CubemapCodeKind::kPulse);
  EXPECT_EQ(out.size(), 9u + 5 * 2);
  EXPECT_EQ(r.rectangles_bytes, 6u + 5 * 2 + 2);  // the chooser's: a cell on each of two faces
  const std::vector<double> d = decode_receiver_cubemap(n, out);
  EXPECT_NEAR(d[70000], 2.0, 2.0 / 510);
  EXPECT_NEAR(d[98303], 1.0, 2.0 / 510);
  Pcg32 rng(19, 20);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const ShellCubemap shell = prepare_shell_cubemap(n, l);
  const Rgb v = dot_receiver_cubemap(out, shell);
  const double dense = dense_dot(d, l).g;
  EXPECT_NEAR(v.g, dense, 1e-6 * std::abs(dense));  // summed in float
  // A run record there: 1 + 4 + 8 + 8r + m bytes, summed by the portable loop.
  for (std::size_t k = 70000; k < 70030; ++k) t[k] = 1.0 + static_cast<double>(k % 7);
  out.clear();
  const EncodedReceiver runs = encode(n, t, out, CubemapBasisChoice::kRuns);
  EXPECT_EQ(runs.kind, CubemapCodeKind::kRuns);
  EXPECT_EQ(out.size(), 13u + 8 * 2 + 30 + 1);  // 70000-70029 and 98303
  const Rgb w = dot_receiver_cubemap(out, shell);
  const Rgb wide = dense_dot(decode_receiver_cubemap(n, out), l);
  EXPECT_NEAR(w.r, wide.r, 1e-6 * std::abs(wide.r));
  EXPECT_NEAR(w.b, wide.b, 1e-6 * std::abs(wide.b));
  // Rectangles there (their coordinates are bytes, whatever W): rows 34-35 of face 4 whole
  // (cells 112-127 of one, 0-13 of the next) and the last cell of face 5, 6 + 5f + m bytes.
  out.clear();
  ASSERT_EQ(encode(n, t, out, CubemapBasisChoice::kRectangles).kind, CubemapCodeKind::kRectangles);
  EXPECT_EQ(out.size(), 6u + 5 * 2 + 2 * 128 + 1);
  const Rgb rect = dot_receiver_cubemap(out, shell);
  const Rgb dense_rect = dense_dot(decode_receiver_cubemap(n, out), l);
  EXPECT_NEAR(rect.g, dense_rect.g, 1e-6 * std::abs(dense_rect.g));
  EXPECT_NEAR(dense_rect.g, wide.g, 1e-12 * std::abs(wide.g));  // the same cells and levels
  // Beyond N = 256 there are none: never chosen, refused when forced, an InputError when read.
  const int big = 512;
  std::vector<double> far(cubemap_texel_count(big), 0.0);
  far[1000] = 1.0;
  out.clear();
  const EncodedReceiver pulse = encode(big, far, out);
  EXPECT_EQ(pulse.kind, CubemapCodeKind::kPulse);
  EXPECT_EQ(pulse.rectangles_bytes, 0u);
  EXPECT_THROW(encode(big, far, out, CubemapBasisChoice::kRectangles), std::invalid_argument);
  const std::vector<std::uint8_t> one = {4, 0, 0, 0x80, 0x3f, 1, 0, 0, 0, 0, 0, 255};  // S = 1
  EXPECT_EQ(decode_receiver_cubemap(n, one)[0], 1.0);
  EXPECT_THROW(parse_cubemap_record(big, one), InputError);
}

TEST(CubemapEncoding, RejectsBadInputAndMalformedRecords) {
  const int n = 8;
  std::vector<std::uint8_t> out;
  std::vector<double> t(cubemap_texel_count(n), 0.0);
  t[5] = -1.0;
  EXPECT_THROW(encode(n, t, out), std::invalid_argument);
  t[5] = NAN;
  EXPECT_THROW(encode(n, t, out), std::invalid_argument);
  EXPECT_THROW(encode(n, std::vector<double>(10, 0.0), out), std::invalid_argument);
  EXPECT_THROW(encode(12, std::vector<double>(cubemap_texel_count(12), 0.0), out),
               std::invalid_argument);
  t[5] = 1.0;
  t[200] = 0.5;
  encode(n, t, out);
  ASSERT_EQ(out.size(), 7u + 3 * 2);
  EXPECT_THROW(parse_cubemap_record(n, std::span(out).first(out.size() - 1)), InputError);
  std::vector<std::uint8_t> bad = out;
  bad[0] = 9;
  EXPECT_THROW(parse_cubemap_record(n, bad), InputError);
  bad = out;
  bad[9] = 0x7f;  // second index → 0x7f7f ≥ 6·8²
  bad[10] = 0x7f;
  EXPECT_THROW(decode_receiver_cubemap(n, bad), InputError);
  Pcg32 rng(21, 22);
  EXPECT_THROW(dot_receiver_cubemap(bad, prepare_shell_cubemap(n, random_radiance(n, rng))),
               InputError);
}

// The record sizes reported, at the default N = 32: a receiver 8 m from a 1 m window
// (a 2 × 2 rectangle of cells, four bytes under pulse), 1 m from a 2 m × 2 m window (runs: the
// window's patch is far from rectangular on the faces so near), under an open sky (runs, two
// bytes under rectangles; Haar is smaller only with a threshold).
TEST(CubemapEncoding, SampleReceiverSizes) {
  const int n = 32;
  struct Sample {
    const char* name;
    std::vector<double> t;
    CubemapCodeKind kind;
  };
  const Sample samples[] = {
      {"far 1x1 window at 8", window_cubemap(n, 8.0, 1.0, 1.0, 2.0), CubemapCodeKind::kRectangles},
      {"near 2x2 window at 1", window_cubemap(n, 1.0, 2.0, 0.5, 2.5), CubemapCodeKind::kRuns},
      {"open sky", sky_cubemap(n), CubemapCodeKind::kRuns}};
  CubemapEncodingStats stats;
  for (const Sample& s : samples) {
    std::vector<std::uint8_t> out;
    const EncodedReceiver r = encode(n, s.t, out);
    const std::size_t cells = std::count_if(s.t.begin(), s.t.end(), [](double v) { return v > 0; });
    std::printf(
        "[sizes] %-22s cells %5zu  pulse %6zu B  runs %6zu B  rectangles %6zu B  haar %6zu B  -> "
        "%s\n",
        s.name, cells, r.pulse_bytes, r.runs_bytes, r.rectangles_bytes, r.haar_bytes,
        kind_name(r.kind));
    EXPECT_EQ(r.kind, s.kind) << s.name;
    add_receiver(stats, r);
    // With a threshold the Haar records shrink; Σ t̂ (a uniform shell) stays within 1%.
    double sum = 0;
    for (double v : s.t) sum += v;
    for (double tau : {0.0, 0.01, 0.02, 0.05}) {
      std::vector<std::uint8_t> o;
      const EncodedReceiver h = encode(n, s.t, o, CubemapBasisChoice::kHaar, tau);
      const std::vector<double> d = decode_receiver_cubemap(n, o);
      double dsum = 0;
      for (double v : d) dsum += v;
      std::printf("[sizes]   haar tau %.2f: %6zu B, max cell error %.3f of max, sum error %.1e\n",
                  tau, h.bytes, max_abs_diff(d, s.t) / max_value(s.t), dsum / sum - 1);
      EXPECT_NEAR(dsum / sum, 1.0, 0.01) << s.name << " " << tau;
    }
  }
  std::printf(
      "[sizes] %.1f B/receiver, pulse %zu runs %zu rectangles %zu haar %zu; all-pulse %zu B, "
      "all-runs %zu B, all-rectangles %zu B, all-haar %zu B\n",
      bytes_per_receiver(stats), stats.pulse, stats.runs, stats.rectangles, stats.haar,
      stats.all_pulse_bytes, stats.all_runs_bytes, stats.all_rectangles_bytes,
      stats.all_haar_bytes);
  EXPECT_EQ(stats.rectangles, 1u);
  EXPECT_EQ(stats.runs, 2u);
}

}  // namespace
}  // namespace relight
