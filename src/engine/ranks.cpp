#include "engine/ranks.h"

namespace relight {

std::vector<std::vector<std::uint8_t>> RankExchange::all_to_all(
    std::vector<std::vector<std::uint8_t>> to) {
  if (to.size() != static_cast<std::size_t>(size())) {
    throw std::invalid_argument("rank exchange: all_to_all needs one piece per rank");
  }
  // Every piece, each after its size; every rank takes its own from every rank's bytes.
  std::vector<std::uint8_t> mine;
  for (const std::vector<std::uint8_t>& piece : to) put_values<std::uint8_t>(mine, piece);
  std::vector<std::vector<std::uint8_t>> all = all_gather(mine);
  std::vector<std::vector<std::uint8_t>> from(to.size());
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k == static_cast<std::size_t>(rank())) {
      from[k] = std::move(to[k]);
      continue;
    }
    std::size_t at = 0;
    for (int j = 0; j <= rank(); ++j) from[k] = take_values<std::uint8_t>(all[k], at);
  }
  return from;
}

std::vector<std::size_t> RankShares::blocks_of(int k) const {
  std::vector<std::size_t> out;
  for (auto b = static_cast<std::size_t>(k); b < block_count();
       b += static_cast<std::size_t>(size())) {
    out.push_back(b);
  }
  return out;
}

std::size_t RankShares::my_receivers() const {
  std::size_t n = 0;
  for (const std::size_t b : my_blocks()) n += last(b) - first(b);
  return n;
}

std::vector<std::vector<std::uint8_t>> RankExchange::gather_to_root(
    std::span<const std::uint8_t> mine) {
  std::vector<std::vector<std::uint8_t>> all = all_gather(mine);
  if (rank() != 0) all.clear();
  return all;
}

std::size_t RankShares::my_receivers_below(std::size_t receiver) const {
  std::size_t n = 0;
  for (const std::size_t b : my_blocks())
    n += std::min(last(b), std::max(first(b), receiver)) - first(b);
  return n;
}

RankShares dealt_blocks(RankExchange& exchange, std::size_t receivers, std::size_t block) {
  if (block < 1) throw std::invalid_argument("rank shares: a block needs at least one receiver");
  return {&exchange, receivers, block};
}

RankShares single_process_shares(std::size_t receivers, std::size_t block) {
  static SingleProcess alone;
  return dealt_blocks(alone, receivers, block);
}

void agree_on_failure(RankExchange& exchange, const std::string& failure) {
  const std::vector<std::uint8_t> mine(failure.begin(), failure.end());
  for (const std::vector<std::uint8_t>& theirs : exchange.all_gather(mine)) {
    if (!theirs.empty()) throw AgreedInputError(std::string(theirs.begin(), theirs.end()));
  }
}

std::uint64_t sum_over_ranks(RankExchange& exchange, std::uint64_t mine) {
  std::uint64_t sum = 0;
  for (const std::uint64_t v : all_gather_values(exchange, mine)) sum += v;
  return sum;
}

void gather_block_records(const RankShares& ranks, const RecordOf& record,
                          std::size_t blocks_per_round, const RecordSink* sink) {
  const auto n = static_cast<std::size_t>(ranks.size());
  const std::size_t blocks = ranks.block_count(), mine = ranks.my_blocks().size();
  const std::size_t m = std::max<std::size_t>(1, blocks_per_round);
  // Round r: every rank's local blocks [r·m, (r + 1)·m), which are the blocks [r·m·n,
  // (r + 1)·m·n) of all (block b is rank b mod n's local block b / n). Each rank sends its
  // blocks' sizes, then their bytes.
  for (std::size_t first = 0; first * n < blocks; first += m) {
    std::vector<std::uint64_t> sizes;
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = first; i < std::min(mine, first + m); ++i) {
      const std::span<const std::uint8_t> r = record(i);
      sizes.push_back(r.size());
      bytes.insert(bytes.end(), r.begin(), r.end());
    }
    std::vector<std::uint8_t> round;
    put_values<std::uint64_t>(round, sizes);
    round.insert(round.end(), bytes.begin(), bytes.end());
    const std::vector<std::vector<std::uint8_t>> all = ranks.exchange->gather_to_root(round);
    if (sink == nullptr) continue;
    // Each rank's records of this round: (offset, size) in its bytes.
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> records(n);
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t at = 0;
      const std::vector<std::uint64_t> theirs = take_values<std::uint64_t>(all.at(k), at);
      for (const std::uint64_t size : theirs) {
        if (all[k].size() - at < size)
          throw std::runtime_error("rank exchange: a record cut short");
        records[k].emplace_back(at, static_cast<std::size_t>(size));
        at += static_cast<std::size_t>(size);
      }
    }
    for (std::size_t b = first * n; b < std::min(blocks, (first + m) * n); ++b) {
      const std::size_t k = b % n, i = b / n - first;
      if (i >= records[k].size())
        throw std::runtime_error("rank exchange: a rank's blocks missing");
      (*sink)(std::span(all[k]).subspan(records[k][i].first, records[k][i].second));
    }
  }
}

}  // namespace relight
