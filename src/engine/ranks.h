// The processes of one precompute (`mpirun -n N relight precompute`). The receivers are dealt to
// the N ranks in blocks (RankShares below; the transfer's blocks of kBlock receivers,
// engine/transfer_blocks.h). Each rank traces its own blocks' rows of every per-receiver phase —
// the gather operator's rays, each luminaire's direct visibility, each portal's cubemaps, the
// near-field transfer — against the whole scene (every rank holds the scene and its Embree BVH).
// What the bounce and the file need of a rank's rows stays with it: its rows of the gather
// operator, the direct columns, the bounce's result and the packed transfer (as its local rows,
// RankShares::local_row); each bounce sweep the ranks send each other the reflected light of the
// vertices their rows read (engine/bounce_solver.cpp), and rank 0 gathers every rank's blocks as it
// writes the file (gather_block_records), the direct phases' records too (luminaire geometry,
// cubemaps, near-field transfer); only small per-block summaries are shared whole
// (share_block_records). Every receiver's rays are seeded by its own index
// (engine/gather_operator.h), so the rows, and the file, do not depend on how many ranks made them.
// Pinned by tests/engine/ranks_test.cpp (blocks, exchanges, the gather operator and the bounce with
// ranks as threads) and tests/cli/mpi_precompute_test.cpp (`mpirun -n 2` against one process, byte
// for byte).
//
// The precompute knows nothing of MPI: the exchange is the interface below, which
// engine/mpi_ranks.h implements over MPI; a process alone is SingleProcess.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/input_error.h"

namespace relight {

class RankExchange {
 public:
  virtual ~RankExchange() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Collective: every rank passes its bytes and gets every rank's, in rank order.
  virtual std::vector<std::vector<std::uint8_t>> all_gather(std::span<const std::uint8_t> mine) = 0;
  // Collective: `to[k]` goes to rank k (one piece per rank); returns the piece each rank sent
  // this one, in rank order (this rank's own piece kept in place). This default goes through
  // all_gather, so every rank receives every piece; MPI sends each piece to its rank alone.
  // Throws std::invalid_argument when `to` has not one piece per rank.
  virtual std::vector<std::vector<std::uint8_t>> all_to_all(
      std::vector<std::vector<std::uint8_t>> to);
  // Collective: rank 0 gets every rank's bytes in rank order, the others nothing. This default
  // goes through all_gather; MPI sends each rank's bytes to rank 0 alone.
  virtual std::vector<std::vector<std::uint8_t>> gather_to_root(std::span<const std::uint8_t> mine);
  // Seconds spent in all_gather so far, waiting for other ranks included.
  virtual double exchange_seconds() const = 0;
  // Bytes all_gather has received from other ranks so far.
  virtual std::uint64_t exchange_bytes() const = 0;
};

// A process alone: rank 0 of 1.
class SingleProcess final : public RankExchange {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::vector<std::uint8_t>> all_gather(std::span<const std::uint8_t> mine) override {
    return {std::vector<std::uint8_t>(mine.begin(), mine.end())};
  }
  double exchange_seconds() const override { return 0; }
  std::uint64_t exchange_bytes() const override { return 0; }
};

// The receivers dealt to the ranks in blocks, in turn: block b (receivers [b·block, (b+1)·block))
// goes to rank b mod N. Dealt so, each rank gets blocks from every part of the room — near the
// window and far from it, vertices and sensors — and the ranks' costs even out without a cost
// model (contiguous shares left one rank 50 % more portal work than the other on the demo room).
struct RankShares {
  RankExchange* exchange = nullptr;
  std::size_t receivers = 0;
  std::size_t block = 64;

  int rank() const { return exchange->rank(); }
  int size() const { return exchange->size(); }
  bool alone() const { return exchange->size() == 1; }
  std::size_t block_count() const { return (receivers + block - 1) / block; }
  std::size_t first(std::size_t b) const { return b * block; }
  std::size_t last(std::size_t b) const { return std::min(receivers, (b + 1) * block); }
  // The rank whose block holds `receiver`.
  int owner(std::size_t receiver) const {
    return static_cast<int>((receiver / block) % static_cast<std::size_t>(size()));
  }
  // Rank k's blocks, in order: k, k + N, k + 2N, …
  std::vector<std::size_t> blocks_of(int k) const;
  std::vector<std::size_t> my_blocks() const { return blocks_of(rank()); }
  // Receivers in this rank's blocks.
  std::size_t my_receivers() const;
  // This rank's rows in order, its blocks one after another (only the last block of all may be
  // short, and it is its rank's last): the local row of one of its receivers, and back.
  std::size_t local_row(std::size_t receiver) const {
    return receiver / block / static_cast<std::size_t>(size()) * block + receiver % block;
  }
  std::size_t receiver_of_local_row(std::size_t row) const {
    return first(row / block * static_cast<std::size_t>(size()) +
                 static_cast<std::size_t>(rank())) +
           row % block;
  }
  // This rank's rows before receiver `receiver` (the local rows of the receivers below it).
  std::size_t my_receivers_below(std::size_t receiver) const;
};

// `receivers` in blocks of `block` dealt to the ranks of `exchange`. Throws
// std::invalid_argument for block < 1.
RankShares dealt_blocks(RankExchange& exchange, std::size_t receivers, std::size_t block);

// This process alone: every block its own.
RankShares single_process_shares(std::size_t receivers, std::size_t block);

// Bad input that every rank knows of (agree_on_failure): each rank ends without waiting for the
// others, and only rank 0 reports it.
struct AgreedInputError : InputError {
  using InputError::InputError;
};

// Collective: `failure` is this rank's error ("WHERE: reason"), empty for none. When any rank
// failed, every rank throws AgreedInputError with the first failing rank's message. For checks
// that may fail on some ranks and not others (a file one machine lacks, its memory), made before
// an exchange that a failed rank would leave the others waiting in.
void agree_on_failure(RankExchange& exchange, const std::string& failure);

// Every rank's `mine`, in rank order (collective).
template <typename T>
std::vector<T> all_gather_values(RankExchange& exchange, const T& mine) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<std::uint8_t> bytes(sizeof(T));
  std::memcpy(bytes.data(), &mine, sizeof(T));
  std::vector<T> out;
  for (const std::vector<std::uint8_t>& b : exchange.all_gather(bytes)) {
    if (b.size() != sizeof(T)) throw std::runtime_error("rank exchange: a value of another size");
    T v;
    std::memcpy(&v, b.data(), sizeof(T));
    out.push_back(v);
  }
  return out;
}

// Σ over ranks of `mine` (collective).
std::uint64_t sum_over_ranks(RankExchange& exchange, std::uint64_t mine);

// Records of varying length per block (a chunk of a gather operator's rows, of encoded
// cubemaps): `put(b, bytes)` appends this rank's block b's record (put_values below), each of
// its blocks in order; on return (collective) `take(b, record, at)` has read every other rank's
// block b from its ranks' bytes, advancing `at`.
template <typename Put, typename Take>
void share_block_records(const RankShares& ranks, Put put, Take take) {
  std::vector<std::uint8_t> bytes;
  for (const std::size_t b : ranks.my_blocks()) put(b, bytes);
  const std::vector<std::vector<std::uint8_t>> all = ranks.exchange->all_gather(bytes);
  for (int k = 0; k < ranks.size(); ++k) {
    if (k == ranks.rank()) continue;
    const std::vector<std::uint8_t>& theirs = all[static_cast<std::size_t>(k)];
    std::size_t at = 0;
    for (const std::size_t b : ranks.blocks_of(k)) take(b, std::span(theirs), at);
    if (at != theirs.size()) throw std::runtime_error("rank exchange: a share of another size");
  }
}

// Collective: every rank's records, one per block of its own (its i-th block's bytes are
// `record(i)`, i < its block count), to rank 0, which hands them to `sink` in the order of the
// blocks (the other ranks pass none): a section of the file gathered as rank 0 writes it. In
// rounds of `blocks_per_round` blocks from each rank, so that rank 0 holds one round at a time.
using RecordOf = std::function<std::span<const std::uint8_t>(std::size_t)>;
using RecordSink = std::function<void(std::span<const std::uint8_t>)>;
void gather_block_records(const RankShares& ranks, const RecordOf& record,
                          std::size_t blocks_per_round, const RecordSink* sink);

// What rank 0 receives a round when it gathers blocks of fixed size (64 MB).
inline constexpr std::size_t kGatherRoundBytes = std::size_t{64} << 20;

// Collective: `data` holds `stride` values per receiver (row-major rows, every receiver's place),
// each rank having filled its own blocks' rows; rank 0's `sink` receives every block's rows in
// order (gather_block_records), the others pass none.
template <typename T>
void gather_rows(const RankShares& ranks, std::size_t stride, std::span<const T> data,
                 const RecordSink* sink) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (data.size() != ranks.receivers * stride) {
    throw std::invalid_argument("rank exchange: rows of another size");
  }
  const std::vector<std::size_t> mine = ranks.my_blocks();
  const std::size_t block_bytes = std::max<std::size_t>(1, ranks.block * stride * sizeof(T));
  gather_block_records(
      ranks,
      [&](std::size_t i) {
        const T* first = data.data() + ranks.first(mine[i]) * stride;
        return std::span(reinterpret_cast<const std::uint8_t*>(first),
                         (ranks.last(mine[i]) - ranks.first(mine[i])) * stride * sizeof(T));
      },
      kGatherRoundBytes / (static_cast<std::size_t>(ranks.size()) * block_bytes), sink);
}

// Appends the bytes of `values` to `out`, and reads them back from `in` at `at` (advanced);
// for the exchanges of records whose length varies per receiver.
template <typename T>
void put_values(std::vector<std::uint8_t>& out, std::span<const T> values) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::uint64_t n = values.size();
  const auto* p = reinterpret_cast<const std::uint8_t*>(&n);
  out.insert(out.end(), p, p + sizeof n);
  const auto* v = reinterpret_cast<const std::uint8_t*>(values.data());
  out.insert(out.end(), v, v + values.size() * sizeof(T));
}

template <typename T>
std::vector<T> take_values(std::span<const std::uint8_t> in, std::size_t& at) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::uint64_t n = 0;
  if (in.size() - at < sizeof n) throw std::runtime_error("rank exchange: a record cut short");
  std::memcpy(&n, in.data() + at, sizeof n);
  at += sizeof n;
  if ((in.size() - at) / sizeof(T) < n) {
    throw std::runtime_error("rank exchange: a record cut short");
  }
  std::vector<T> out(static_cast<std::size_t>(n));
  if (n > 0) std::memcpy(out.data(), in.data() + at, out.size() * sizeof(T));
  at += out.size() * sizeof(T);
  return out;
}

}  // namespace relight
