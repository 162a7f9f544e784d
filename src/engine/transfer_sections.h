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

// Collective: each rank's blocks of a section (`mine`, its blocks of `block_bytes` in local
// order) to rank 0, which hands every block in file order to `sink` (the others pass none). In
// rounds of at most kGatherRoundBytes received: rank 0 holds one round, never the section.
void gather_blocks(const RankShares& ranks, std::span<const std::byte> mine,
                   std::size_t block_bytes, const RltWriter::Sink* sink);

// Runs `gather` (a collective over records, engine/ranks.h) with the file's `sink` as a
// RecordSink, or with none where `sink` is null (the ranks that only send).
template <typename Gather>
void gather_into(const RltWriter::Sink* sink, const Gather& gather) {
  if (sink == nullptr) {
    gather(nullptr);
    return;
  }
  const RecordSink records = [sink](std::span<const std::uint8_t> block) {
    (*sink)(std::as_bytes(block));
  };
  gather(&records);
}

// Where a source kind writes its .rlt sections, whichever rank this process is: the process that
// writes the file (rank 0, or a process alone) adds them to its writer — on several ranks as
// sections gathered from every rank while the file is written — and every other rank sends its
// share of the same sections to it. A kind writes its sections once, through a sink, so the
// ranks' collectives come in the same order on every rank by construction.
class SectionSink {
 public:
  // This process writes the file with `writer`.
  SectionSink(RltWriter& writer, const RankShares& ranks) : writer_(&writer), ranks_(ranks) {}
  // Another rank: sends its share of each section to the one that writes.
  explicit SectionSink(const RankShares& ranks) : ranks_(ranks) {}

  // The writer when this process writes the file, else null: for what only it holds (text,
  // metadata) and for a section a process alone adds whole.
  RltWriter* writer() const { return writer_; }
  const RankShares& ranks() const { return ranks_; }
  bool alone() const { return ranks_.alone(); }

  // A section of `stride` floats per receiver, `rows` holding every receiver's place and this
  // rank's own blocks filled in (alone: all of them).
  void rows(std::uint32_t type, const std::string& name, std::span<const float> rows,
            std::size_t stride);
  // A blocked SH transfer: `t` views this rank's blocks (RankShares local order,
  // engine/column_registry.h pack_indirect_blocks; alone: all), `block_bytes` the bytes of one.
  void transfer(std::uint32_t type, const std::string& name, BlockedTransfer t,
                std::size_t block_bytes);
  // On several ranks, a section gathered by `gather`, a collective every rank runs: the writing
  // rank while the file is written, handing the section's bytes to the file's sink; the others
  // at once, with none.
  using Gather = std::function<void(const RltWriter::Sink* sink)>;
  void gathered(std::uint32_t type, const std::string& name, RltElement element, Gather gather,
                std::uint32_t flags = 0);

 private:
  RltWriter* writer_ = nullptr;
  RankShares ranks_;
};

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
