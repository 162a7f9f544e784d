// Stored SH transfer (engine/transfer_blocks.h, transfer_sections.h): binary16 with a power-of-two
// scale keeps every value within 2⁻¹¹ relative over a range of 2²⁹ below the largest; the weighted
// sum over it (F16C and table alike) is the float sum of the decoded values; a section comes back
// from a .rlt bit for bit with its scale.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "engine/transfer_blocks.h"
#include "engine/transfer_sections.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

// Values over 28 binary orders of magnitude, both signs.
std::vector<float> spread_values(std::size_t n, float largest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> exponent(-28, 0);
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = largest * std::exp2(exponent(rng)) * (i % 3 == 0 ? -1.0f : 1.0f);
  }
  v[n / 2] = largest;
  return v;
}

TEST(TransferBlocks, Fp16KeepsEveryValueWithinTwoToTheMinusElevenOverTwentyEightOctaves) {
  for (const float largest : {3.7e-6f, 0.02f, 1.0f, 5.0e4f}) {
    const std::vector<float> values = spread_values(4096, largest);
    const PackedTransfer packed = store_blocks(values, TransferStorage::fp16);
    ASSERT_TRUE(packed.f32.empty());
    ASSERT_EQ(packed.f16.size(), values.size());
    // A power of two putting the largest magnitude in [2^14, 2^15).
    EXPECT_EQ(std::exp2(std::round(std::log2(packed.scale))), packed.scale);
    EXPECT_GE(largest / packed.scale, 16384.0f);
    EXPECT_LT(largest / packed.scale, 32768.0f);
    std::vector<float> back(values.size());
    packed.view().copy_to(0, back);
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_NEAR(back[i], values[i], std::abs(values[i]) * 0x1p-11f) << i << " of " << largest;
    }
  }
  const PackedTransfer kept = store_blocks({1, 2, 3}, TransferStorage::fp32);
  EXPECT_EQ(kept.f32, (std::vector<float>{1, 2, 3}));
  EXPECT_TRUE(kept.f16.empty());
  const PackedTransfer zeros = store_blocks(std::vector<float>(64, 0.0f), TransferStorage::fp16);
  EXPECT_EQ(zeros.scale, 1.0f);
}

TEST(TransferBlocks, TheHalfSumIsTheFloatSumOfTheDecodedValuesWithF16cAndWithoutIt) {
  const std::size_t k = 9, blocks = 3;
  const std::vector<float> values = spread_values(blocks * k * 3 * kBlock, 0.35f);
  const PackedTransfer packed = store_blocks(values, TransferStorage::fp16);
  std::vector<float> decoded(values.size());
  packed.view().copy_to(0, decoded);
  std::vector<float> w(3 * k);
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = 100.0f * std::sin(float(i) + 0.5f);
  for (std::size_t b = 0; b < blocks; ++b) {
    float expected[3][kBlock] = {}, table[3][kBlock] = {}, f16c[3][kBlock] = {},
          any[3][kBlock] = {};
    add_weighted_block(decoded.data() + b * k * 3 * kBlock, k, w.data(), expected);
    const RltHalf* t = packed.f16.data() + b * k * 3 * kBlock;
    add_weighted_half_block(t, k, w.data(), packed.scale, table, false);
    if (has_f16c()) add_weighted_half_block(t, k, w.data(), packed.scale, f16c, true);
    add_weighted_block(packed.view(), b, k, w.data(), any);
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t i = 0; i < kBlock; ++i) {
        double magnitude = 0;  // Σ |w · t|: what rounding in the sum is relative to
        for (std::size_t basis = 0; basis < k; ++basis) {
          magnitude += std::abs(w[3 * basis + c] * decoded[((b * k + basis) * 3 + c) * kBlock + i]);
        }
        const double tolerance = 1e-6 * magnitude;
        EXPECT_NEAR(table[c][i], expected[c][i], tolerance);
        if (has_f16c()) {
          EXPECT_NEAR(f16c[c][i], expected[c][i], tolerance);
        }
        EXPECT_NEAR(any[c][i], expected[c][i], tolerance);
      }
    }
  }
}

TEST(TransferBlocks, AnFp16SectionComesBackBitForBitWithItsScale) {
  const testing::TempDir dir;
  const PackedTransfer half = store_blocks(spread_values(640, 2.5e-3f), TransferStorage::fp16);
  const PackedTransfer single = store_blocks(spread_values(640, 2.5e-3f), TransferStorage::fp32);
  RltWriter w;
  add_transfer_section(w, rlt_fourcc("TIH0"), "half", half);
  add_transfer_section(w, rlt_fourcc("TIF0"), "single", single);
  w.write(dir.path() / "t.rlt");
  const RltFile file = RltFile::open(dir.path() / "t.rlt");
  const BlockedTransfer h = transfer_section(file, rlt_fourcc("TIH0"));
  ASSERT_TRUE(h.half());
  EXPECT_EQ(h.scale, half.scale);
  ASSERT_EQ(h.size(), half.f16.size());
  for (std::size_t i = 0; i < h.size(); ++i) EXPECT_EQ(h.f16[i].bits, half.f16[i].bits) << i;
  EXPECT_EQ(h.size_bytes(), 640u * 2);
  const BlockedTransfer f = transfer_section(file, rlt_fourcc("TIF0"));
  ASSERT_FALSE(f.half());
  EXPECT_EQ(std::vector<float>(f.f32.begin(), f.f32.end()), single.f32);
}

}  // namespace
}  // namespace relight
