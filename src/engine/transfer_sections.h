// A source's blocked SH transfer as a .rlt section (docs/rlt-format.md, "Stored transfer"):
// element f32, or f16 with the scale's exponent in the section's flags (the scale 2^(flags − 128),
// engine/transfer_blocks.h). Pinned by tests/engine/transfer_blocks_test.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/ranks.h"
#include "engine/transfer_blocks.h"
#include "store/rlt_file.h"
#include "store/rlt_writer.h"

namespace relight {

// Adds `t` as section `type`; `t` must outlive the writer's write().
void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          const PackedTransfer& t);

// Several ranks (collective): `t` views this rank's blocks of the section (RankShares local order,
// engine/column_registry.h pack_indirect_blocks), `block_bytes` the bytes of one block. Rank 0 adds
// the section, its blocks gathered from every rank in file order while w.write() runs
// (gather_blocks); the other ranks call send_transfer_section for the same sections in the same
// order.
void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          BlockedTransfer t, const RankShares& ranks, std::size_t block_bytes);
void send_transfer_section(BlockedTransfer t, const RankShares& ranks, std::size_t block_bytes);

// Collective: each rank's blocks of a section (`mine`, its blocks of `block_bytes` in local
// order) to rank 0, which hands every block in file order to `sink` (the others pass none). In
// rounds of at most kGatherRoundBytes received: rank 0 holds one round, never the section.
void gather_blocks(const RankShares& ranks, std::span<const std::byte> mine,
                   std::size_t block_bytes, const RltWriter::Sink* sink);

// Several ranks (collective): a section of `stride` floats per receiver, `rows` holding every
// receiver's place and this rank's own blocks filled in; rank 0 adds it, gathered from every rank
// as it is written (gather_rows), the others call send_row_section in the same order. One process
// adds `rows` as it is.
void add_row_section(RltWriter& w, std::uint32_t type, const std::string& name,
                     std::span<const float> rows, std::size_t stride, const RankShares& ranks);
void send_row_section(std::span<const float> rows, std::size_t stride, const RankShares& ranks);

// Several ranks: an offsets section (records gathered block by block, engine/ranks.h) from its
// records' sizes. `gather_sizes` runs the gather of blocks of uint32 sizes, in file order, into
// the sink it is given; `sink` gets their running offsets as Offset values, then the total.
template <typename Offset>
void write_running_offsets(const RltWriter::Sink& sink,
                           const std::function<void(const RecordSink&)>& gather_sizes) {
  Offset offset = 0;
  std::vector<Offset> offsets;
  gather_sizes([&](std::span<const std::uint8_t> block) {
    offsets.resize(block.size() / sizeof(std::uint32_t));
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      std::uint32_t size = 0;
      std::memcpy(&size, block.data() + i * sizeof size, sizeof size);
      offsets[i] = std::exchange(offset, offset + size);
    }
    sink(std::as_bytes(std::span(offsets)));
  });
  sink(std::as_bytes(std::span(&offset, 1)));
}

// The section `type` as written by add_transfer_section. InputError "FILE: reason" when it is
// missing or of another element type.
BlockedTransfer transfer_section(const RltFile& file, std::uint32_t type);

}  // namespace relight
