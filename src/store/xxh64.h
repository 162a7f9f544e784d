// XXH64, the 64-bit hash that checksums every .rlt section (docs/rlt-format.md).
//
// Why this hash: .rlt sections are hundreds of MB and are all verified when a file is
// opened, so the checksum must run near memory speed. XXH64 consumes 32-byte stripes in
// four independent 64-bit lanes (about 10 GB/s on one core, several times CRC-32C with
// slicing-by-8) and detects any change with probability 1 - 2^-64. It guards against
// truncation and bit rot, not against an adversary.
//
// Implemented from the published specification, "xxHash fast digest algorithm" v0.1.1,
// Yann Collet, https://github.com/Cyan4973/xxHash/blob/dev/doc/xxhash_spec.md (§ XXH64);
// tests/store/xxh64_test.cpp checks it against the reference vectors of the xxHash sanity
// check.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace relight {

// XXH64 of bytes with the given seed, in one call.
std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed = 0);

// The same digest computed over data that arrives in pieces (the writer hashes each
// section while streaming it to disk). Any split of the input gives the same digest.
class Xxh64 {
 public:
  explicit Xxh64(std::uint64_t seed = 0);

  void update(std::span<const std::byte> bytes);
  std::uint64_t digest() const;

 private:
  std::uint64_t seed_;
  std::array<std::uint64_t, 4> lanes_;
  std::array<std::byte, 32> pending_{};  // the start of an incomplete stripe
  std::size_t pending_size_ = 0;
  std::uint64_t total_size_ = 0;
};

}  // namespace relight
