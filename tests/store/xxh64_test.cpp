// XXH64 agrees with the reference implementation's published vectors, gives the same
// digest however the input is split, and reports its throughput (never asserted: timing
// on a shared machine is not a test).
#include "store/xxh64.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <string_view>
#include <vector>

namespace relight {
namespace {

std::span<const std::byte> bytes(std::string_view text) {
  return std::as_bytes(std::span(text));
}

// The buffer of xxHash's sanity check (xsum_sanity_check.c, 101 bytes): each byte is the
// top byte of a 32-bit generator that squares itself.
std::vector<std::byte> sanity_buffer() {
  std::vector<std::byte> buffer(101);
  std::uint32_t generator = 2654435761u;
  for (std::byte& b : buffer) {
    b = static_cast<std::byte>(generator >> 24);
    generator *= generator;
  }
  return buffer;
}

TEST(Xxh64, MatchesTheReferenceSanityVectors) {
  const std::vector<std::byte> buffer = sanity_buffer();
  const std::span<const std::byte> all(buffer);
  constexpr std::uint64_t kPrime = 2654435761u;
  EXPECT_EQ(xxh64({}, 0), 0xEF46DB3751D8E999ull);
  EXPECT_EQ(xxh64({}, kPrime), 0xAC75FDA2929B17EFull);
  EXPECT_EQ(xxh64(all.first(1), 0), 0x4FCE394CC88952D8ull);
  EXPECT_EQ(xxh64(all.first(1), kPrime), 0x739840CB819FA723ull);
  EXPECT_EQ(xxh64(all.first(14), 0), 0xCFFA8DB881BC3A3Dull);
  EXPECT_EQ(xxh64(all.first(14), kPrime), 0x5B9611585EFCC9CBull);
  EXPECT_EQ(xxh64(all, 0), 0x0EAB543384F878ADull);
  EXPECT_EQ(xxh64(all, kPrime), 0xCAA65939306F1E21ull);
}

TEST(Xxh64, MatchesTheReferenceTextVectors) {
  EXPECT_EQ(xxh64(bytes("a")), 0xD24EC4F1A98C6E5Bull);
  EXPECT_EQ(xxh64(bytes("abc")), 0x44BC2CF5AD770999ull);
  EXPECT_EQ(xxh64(bytes("Nobody inspects the spammish repetition")), 0xFBCEA83C8A378BF1ull);
}

TEST(Xxh64, StreamingGivesTheOneShotDigestForEverySplit) {
  std::vector<std::byte> data(150);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::byte>(i * 37 + 11);
  const std::span<const std::byte> all(data);
  const std::uint64_t expected = xxh64(all, 7);
  int mismatches = 0;
  for (std::size_t a = 0; a <= data.size(); ++a) {
    for (std::size_t b = a; b <= data.size(); ++b) {
      Xxh64 hash(7);
      hash.update(all.subspan(0, a));
      hash.update(all.subspan(a, b - a));
      hash.update(all.subspan(b));
      if (hash.digest() != expected) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(Xxh64, EveryFlippedBitChangesTheDigest) {
  std::vector<std::byte> data(100, std::byte{0x5A});
  const std::uint64_t clean = xxh64(data);
  int unchanged = 0;
  for (std::size_t i = 0; i < data.size() * 8; ++i) {
    data[i / 8] ^= std::byte(1u << (i % 8));
    if (xxh64(data) == clean) ++unchanged;
    data[i / 8] ^= std::byte(1u << (i % 8));
  }
  EXPECT_EQ(unchanged, 0);
}

TEST(Xxh64, ReportsThroughputOn64MiB) {
  std::vector<std::byte> data(64u << 20);
  for (std::size_t i = 0; i < data.size(); i += 4096) data[i] = static_cast<std::byte>(i >> 12);
  xxh64(std::span(data).first(1 << 20));  // warm up
  double best_seconds = 1e9;
  std::uint64_t digest = 0;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    digest ^= xxh64(data);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    best_seconds = std::min(best_seconds, took.count());
  }
  const double gb_per_s = static_cast<double>(data.size()) / best_seconds / 1e9;
  RecordProperty("xxh64_GB_per_s", std::to_string(gb_per_s));
  std::cout << "[ info     ] xxh64 over 64 MiB: " << gb_per_s << " GB/s (best of 3)\n";
  EXPECT_NE(digest, 0u);  // keeps the work observable
}

}  // namespace
}  // namespace relight
