#include "engine/transfer_sections.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/input_error.h"

namespace relight {

namespace {
constexpr int kExponentBias = 128;
}  // namespace

void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          const PackedTransfer& t) {
  if (t.f16.empty()) {
    w.add_f32(type, name, t.f32);
    return;
  }
  const auto flags = static_cast<std::uint32_t>(std::ilogb(t.scale) + kExponentBias);
  w.add_f16(type, name, t.f16, flags);
}

void gather_blocks(const RankShares& ranks, std::span<const std::byte> mine,
                   std::size_t block_bytes, const RltWriter::Sink* sink) {
  if (block_bytes == 0 || mine.size() % block_bytes != 0) {
    throw std::invalid_argument("gather_blocks: not a whole number of blocks");
  }
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(mine.data()),
                                            mine.size());
  const RecordSink to_sink = [sink](std::span<const std::uint8_t> block) {
    (*sink)(std::as_bytes(block));
  };
  gather_block_records(
      ranks, [&](std::size_t i) { return bytes.subspan(i * block_bytes, block_bytes); },
      kGatherRoundBytes / (static_cast<std::size_t>(ranks.size()) * block_bytes),
      sink != nullptr ? &to_sink : nullptr);
}

void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          BlockedTransfer t, const RankShares& ranks, std::size_t block_bytes) {
  const bool half = t.half();
  const auto flags =
      half ? static_cast<std::uint32_t>(std::ilogb(t.scale) + kExponentBias) : std::uint32_t{0};
  const RltElement element = half ? RltElement::f16 : RltElement::f32;
  if (ranks.alone()) {
    w.add_section(type, name, t.bytes(), element, flags);
    return;
  }
  w.add_produced_section(
      type, name,
      [t, ranks, block_bytes](const RltWriter::Sink& sink) {
        gather_blocks(ranks, t.bytes(), block_bytes, &sink);
      },
      element, flags);
}

void send_transfer_section(BlockedTransfer t, const RankShares& ranks, std::size_t block_bytes) {
  gather_blocks(ranks, t.bytes(), block_bytes, nullptr);
}

void add_row_section(RltWriter& w, std::uint32_t type, const std::string& name,
                     std::span<const float> rows, std::size_t stride, const RankShares& ranks) {
  if (ranks.alone()) {
    w.add_f32(type, name, rows);
    return;
  }
  w.add_produced_section(
      type, name,
      [rows, stride, ranks](const RltWriter::Sink& sink) {
        const RecordSink to_sink = [&sink](std::span<const std::uint8_t> block) {
          sink(std::as_bytes(block));
        };
        gather_rows(ranks, stride, rows, &to_sink);
      },
      RltElement::f32);
}

void send_row_section(std::span<const float> rows, std::size_t stride, const RankShares& ranks) {
  gather_rows(ranks, stride, rows, nullptr);
}

BlockedTransfer transfer_section(const RltFile& file, std::uint32_t type) {
  const RltSectionInfo& info = file.info(type);
  BlockedTransfer t;
  if (info.element != RltElement::f16) {
    t.f32 = file.view<float>(type);
    return t;
  }
  t.f16 = file.view<RltHalf>(type);
  const auto exponent = static_cast<int>(info.flags & 0xFF) - kExponentBias;
  t.scale = std::ldexp(1.0f, exponent);
  if (t.f16.empty()) t.scale = 1;
  return t;
}

}  // namespace relight
