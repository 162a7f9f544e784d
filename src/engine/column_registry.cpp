#include "engine/column_registry.h"

#include <algorithm>
#include <stdexcept>

#include "engine/transfer_blocks.h"

namespace relight {

ColumnRange ColumnRegistry::add(std::string owner, Eigen::Index count) {
  if (count < 0) throw std::invalid_argument("ColumnRegistry: negative count for " + owner);
  const ColumnRange r{columns_, count};
  columns_ += count;
  owners_.push_back(std::move(owner));
  return r;
}

void DirectColumns::set(ColumnRange r, const Eigen::MatrixXf& every_receiver) {
  if (every_receiver.rows() != static_cast<Eigen::Index>(ranks_.receivers) ||
      every_receiver.cols() != r.count) {
    throw std::invalid_argument("DirectColumns: a range of another size");
  }
  if (ranks_.alone()) {
    of(r) = every_receiver;
    return;
  }
  for (Eigen::Index l = 0; l < matrix_.rows(); ++l) {
    matrix_.row(l).segment(r.first, r.count) = every_receiver.row(
        static_cast<Eigen::Index>(ranks_.receiver_of_local_row(static_cast<std::size_t>(l))));
  }
}

PackedTransfer pack_indirect_blocks(const BounceResult& result, ColumnRange r,
                                    TransferStorage storage) {
  // Read in place: copies of the three channels would hold them twice at the precompute's peak.
  std::vector<float> blocked = pack_blocks(
      {indirect_of(result, 0, r), indirect_of(result, 1, r), indirect_of(result, 2, r)});
  if (result.ranks == nullptr || result.ranks->alone())
    return store_blocks(std::move(blocked), storage);
  float largest = largest_magnitude(blocked);
  for (const float theirs : all_gather_values(*result.ranks->exchange, largest)) {
    largest = std::max(largest, theirs);
  }
  return store_blocks(std::move(blocked), storage, largest);
}

}  // namespace relight
