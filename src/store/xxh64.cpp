// XXH64 after its specification (see xxh64.h): stripes of 32 bytes feed four lanes;
// the lanes are merged, the remaining bytes mixed in, and the result avalanched.
#include "store/xxh64.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace relight {

namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t kPrime4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t kPrime5 = 0x27D4EB2F165667C5ull;
constexpr std::size_t kStripe = 32;

template <class T>
T read_le(const std::byte* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    T swapped = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      swapped = (swapped << 8) | ((value >> (8 * i)) & 0xFF);
    value = swapped;
  }
  return value;
}

std::uint64_t round(std::uint64_t acc, std::uint64_t lane) {
  acc += lane * kPrime2;
  return std::rotl(acc, 31) * kPrime1;
}

std::uint64_t merge(std::uint64_t acc, std::uint64_t lane) {
  acc ^= round(0, lane);
  return acc * kPrime1 + kPrime4;
}

// Consumes every whole stripe of [p, p + size); returns the number of bytes consumed.
std::size_t consume_stripes(std::array<std::uint64_t, 4>& lanes, const std::byte* p,
                            std::size_t size) {
  std::uint64_t v0 = lanes[0], v1 = lanes[1], v2 = lanes[2], v3 = lanes[3];
  const std::size_t stripes = size / kStripe;
  for (std::size_t s = 0; s < stripes; ++s, p += kStripe) {
    v0 = round(v0, read_le<std::uint64_t>(p));
    v1 = round(v1, read_le<std::uint64_t>(p + 8));
    v2 = round(v2, read_le<std::uint64_t>(p + 16));
    v3 = round(v3, read_le<std::uint64_t>(p + 24));
  }
  lanes = {v0, v1, v2, v3};
  return stripes * kStripe;
}

}  // namespace

Xxh64::Xxh64(std::uint64_t seed)
    : seed_(seed), lanes_{seed + kPrime1 + kPrime2, seed + kPrime2, seed, seed - kPrime1} {}

void Xxh64::update(std::span<const std::byte> bytes) {
  total_size_ += bytes.size();
  const std::byte* p = bytes.data();
  std::size_t left = bytes.size();
  if (pending_size_ > 0) {
    const std::size_t take = std::min(left, kStripe - pending_size_);
    std::memcpy(pending_.data() + pending_size_, p, take);
    pending_size_ += take;
    p += take;
    left -= take;
    if (pending_size_ < kStripe) return;
    consume_stripes(lanes_, pending_.data(), kStripe);
    pending_size_ = 0;
  }
  const std::size_t consumed = consume_stripes(lanes_, p, left);
  p += consumed;
  left -= consumed;
  if (left > 0) std::memcpy(pending_.data(), p, left);
  pending_size_ = left;
}

std::uint64_t Xxh64::digest() const {
  std::uint64_t acc;
  if (total_size_ >= kStripe) {
    acc = std::rotl(lanes_[0], 1) + std::rotl(lanes_[1], 7) + std::rotl(lanes_[2], 12) +
          std::rotl(lanes_[3], 18);
    for (const std::uint64_t lane : lanes_) acc = merge(acc, lane);
  } else {
    acc = seed_ + kPrime5;
  }
  acc += total_size_;

  const std::byte* p = pending_.data();
  std::size_t left = pending_size_;
  for (; left >= 8; left -= 8, p += 8) {
    acc ^= round(0, read_le<std::uint64_t>(p));
    acc = std::rotl(acc, 27) * kPrime1 + kPrime4;
  }
  if (left >= 4) {
    acc ^= std::uint64_t{read_le<std::uint32_t>(p)} * kPrime1;
    acc = std::rotl(acc, 23) * kPrime2 + kPrime3;
    left -= 4;
    p += 4;
  }
  for (; left > 0; --left, ++p) {
    acc ^= std::to_integer<std::uint64_t>(*p) * kPrime5;
    acc = std::rotl(acc, 11) * kPrime1;
  }

  acc ^= acc >> 33;
  acc *= kPrime2;
  acc ^= acc >> 29;
  acc *= kPrime3;
  acc ^= acc >> 32;
  return acc;
}

std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed) {
  Xxh64 hash(seed);
  hash.update(bytes);
  return hash.digest();
}

}  // namespace relight
