// Per-receiver pulse / Haar encoding of the direct portal cubemap
// (sources/portal/cubemap_encoding.h, Yue et al. 2009 §4.1.2): round trips within the stated 8-bit
// bounds, the run-time sparse dot product against the dense one and against the unquantised vector,
// the basis chooser, the byte counts, and the sizes measured on sample receivers (a far window, a
// near window, an open sky).
#include "sources/portal/cubemap_encoding.h"

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
    for (CubemapBasisChoice choice : {CubemapBasisChoice::kPulse, CubemapBasisChoice::kHaar}) {
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
    for (CubemapBasisChoice choice : {CubemapBasisChoice::kPulse, CubemapBasisChoice::kHaar}) {
      std::vector<std::uint8_t> out;
      const EncodedReceiver r = encode(n, t, out, choice);
      const Rgb got = dot_receiver_cubemap(out, shell), exact = dense_dot(t, l);
      Rgb bound;
      if (r.kind == CubemapCodeKind::kPulse) {
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
      std::printf("[dot] %s %s relative error %.2e\n",
                  r.kind == CubemapCodeKind::kPulse ? "pulse" : "haar",
                  &t == &inputs[0]   ? "sparse"
                  : &t == &inputs[1] ? "sky"
                                     : "window",
                  rel);
    }
}

TEST(CubemapEncoding, ChooserPicksPulseForFewCellsAndHaarForSmoothFullCubemap) {
  const int n = 32;
  Pcg32 rng(15, 16);
  std::vector<std::uint8_t> out;
  const EncodedReceiver few = encode(n, sparse_cubemap(n, 10, rng), out);
  EXPECT_EQ(few.kind, CubemapCodeKind::kPulse);
  EXPECT_LT(few.pulse_bytes, few.haar_bytes);
  EXPECT_LE(few.bytes, cubemap_record_bytes(n, CubemapCodeKind::kPulse, 10));
  // A smooth function over the whole sphere.
  std::vector<double> smooth(cubemap_texel_count(n));
  for (std::size_t k = 0; k < smooth.size(); ++k) {
    const Vec3 d = cubemap_texel_direction(n, cubemap_texel_from_index(n, k));
    smooth[k] = 1.0 + 0.5 * d.x + 0.3 * d.y * d.z;
  }
  const EncodedReceiver full = encode(n, smooth, out);
  EXPECT_EQ(full.kind, CubemapCodeKind::kHaar);
  EXPECT_EQ(full.pulse_bytes, cubemap_record_bytes(n, CubemapCodeKind::kPulse, smooth.size()));
  EXPECT_LT(full.haar_bytes, full.pulse_bytes);
  EXPECT_EQ(encode(n, sky_cubemap(n), out).kind, CubemapCodeKind::kHaar);
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
    EXPECT_EQ(r.bytes, buffer.size() - before);
    EXPECT_EQ(r.bytes, std::min(r.pulse_bytes, r.haar_bytes));
    const CubemapRecord rec = parse_cubemap_record(n, std::span(buffer).subspan(before));
    EXPECT_EQ(rec.bytes, r.bytes);
    EXPECT_EQ(rec.bytes, cubemap_record_bytes(n, rec.kind, rec.count));
    if (rec.kind == CubemapCodeKind::kPulse) {
      EXPECT_EQ(rec.bytes, 7 + 3 * rec.count);
    } else if (rec.kind == CubemapCodeKind::kHaar) {
      EXPECT_EQ(rec.bytes, 11 + 3 * rec.count);
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
  EXPECT_EQ(walked.pulse + walked.haar + walked.empty, 5u);
  EXPECT_EQ(walked.pulse_bytes + walked.haar_bytes + 1, buffer.size());
  EXPECT_EQ(walked.pulse_bytes, added.pulse_bytes);
  EXPECT_GE(added.all_pulse_bytes, added.bytes);
  EXPECT_GE(added.all_haar_bytes, added.bytes);
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
  const EncodedReceiver r = encode(n, t, out);
  EXPECT_EQ(r.kind, CubemapCodeKind::kPulse);
  EXPECT_EQ(out.size(), 9u + 5 * 2);
  const std::vector<double> d = decode_receiver_cubemap(n, out);
  EXPECT_NEAR(d[70000], 2.0, 2.0 / 510);
  EXPECT_NEAR(d[98303], 1.0, 2.0 / 510);
  Pcg32 rng(19, 20);
  const std::vector<Rgb> l = random_radiance(n, rng);
  const Rgb v = dot_receiver_cubemap(out, prepare_shell_cubemap(n, l));
  const double dense = dense_dot(d, l).g;
  EXPECT_NEAR(v.g, dense, 1e-6 * std::abs(dense));  // summed in float
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

// The sizes issue 4 asks to report, at the default N = 32: a receiver 8 m from a 1 m window
// (pulse), 1 m from a 2 m × 2 m window (Haar), under an open sky (Haar).
TEST(CubemapEncoding, SampleReceiverSizes) {
  const int n = 32;
  struct Sample {
    const char* name;
    std::vector<double> t;
    CubemapCodeKind kind;
  };
  const Sample samples[] = {
      {"far 1x1 window at 8", window_cubemap(n, 8.0, 1.0, 1.0, 2.0), CubemapCodeKind::kPulse},
      {"near 2x2 window at 1", window_cubemap(n, 1.0, 2.0, 0.5, 2.5), CubemapCodeKind::kHaar},
      {"open sky", sky_cubemap(n), CubemapCodeKind::kHaar}};
  CubemapEncodingStats stats;
  for (const Sample& s : samples) {
    std::vector<std::uint8_t> out;
    const EncodedReceiver r = encode(n, s.t, out);
    const std::size_t cells = std::count_if(s.t.begin(), s.t.end(), [](double v) { return v > 0; });
    std::printf("[sizes] %-22s cells %5zu  pulse %6zu B  haar %6zu B  -> %s\n", s.name, cells,
                r.pulse_bytes, r.haar_bytes, r.kind == CubemapCodeKind::kPulse ? "pulse" : "haar");
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
  std::printf("[sizes] %.1f B/receiver, pulse %zu haar %zu; all-pulse %zu B, all-haar %zu B\n",
              bytes_per_receiver(stats), stats.pulse, stats.haar, stats.all_pulse_bytes,
              stats.all_haar_bytes);
  EXPECT_EQ(stats.pulse, 1u);
  EXPECT_EQ(stats.haar, 2u);
}

}  // namespace
}  // namespace relight
