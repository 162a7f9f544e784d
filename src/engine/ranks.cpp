#include "engine/ranks.h"

namespace relight {

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

void share_rows(const RankShares& ranks, Eigen::MatrixXf& matrix) {
  if (ranks.alone()) return;
  if (static_cast<std::size_t>(matrix.rows()) != ranks.receivers) {
    throw std::invalid_argument("rank exchange: a matrix of another size");
  }
  // Row-major copies of the rows, exchanged as such.
  const auto columns = static_cast<std::size_t>(matrix.cols());
  std::vector<float> rows(ranks.receivers * columns);
  for (const std::size_t b : ranks.my_blocks()) {
    for (std::size_t r = ranks.first(b); r < ranks.last(b); ++r) {
      for (std::size_t c = 0; c < columns; ++c) {
        rows[r * columns + c] = matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
      }
    }
  }
  share_rows(ranks, columns, rows);
  for (std::size_t r = 0; r < ranks.receivers; ++r) {
    for (std::size_t c = 0; c < columns; ++c) {
      matrix(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r * columns + c];
    }
  }
}

}  // namespace relight
