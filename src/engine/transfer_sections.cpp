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
  gather_into(sink, [&](const RecordSink* records) {
    gather_block_records(
        ranks, [&](std::size_t i) { return bytes.subspan(i * block_bytes, block_bytes); },
        kGatherRoundBytes / (static_cast<std::size_t>(ranks.size()) * block_bytes), records);
  });
}

void SectionSink::gathered(std::uint32_t type, const std::string& name, RltElement element,
                           Gather gather, std::uint32_t flags) {
  if (writer_ == nullptr) {
    gather(nullptr);
    return;
  }
  writer_->add_produced_section(
      type, name, [gather = std::move(gather)](const RltWriter::Sink& sink) { gather(&sink); },
      element, flags);
}

void SectionSink::transfer(std::uint32_t type, const std::string& name, BlockedTransfer t,
                           std::size_t block_bytes) {
  const bool half = t.half();
  const auto flags =
      half ? static_cast<std::uint32_t>(std::ilogb(t.scale) + kExponentBias) : std::uint32_t{0};
  const RltElement element = half ? RltElement::f16 : RltElement::f32;
  if (alone()) {
    writer_->add_section(type, name, t.bytes(), element, flags);
    return;
  }
  gathered(
      type, name, element,
      [t, ranks = ranks_, block_bytes](const RltWriter::Sink* sink) {
        gather_blocks(ranks, t.bytes(), block_bytes, sink);
      },
      flags);
}

void SectionSink::rows(std::uint32_t type, const std::string& name, std::span<const float> rows,
                       std::size_t stride) {
  if (alone()) {
    writer_->add_f32(type, name, rows);
    return;
  }
  gathered(
      type, name, RltElement::f32, [rows, stride, ranks = ranks_](const RltWriter::Sink* sink) {
        gather_into(sink,
                    [&](const RecordSink* records) { gather_rows(ranks, stride, rows, records); });
      });
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
