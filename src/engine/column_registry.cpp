#include "engine/column_registry.h"

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

PackedTransfer pack_indirect_blocks(const BounceResult& result, ColumnRange r,
                                    TransferStorage storage) {
  const Eigen::MatrixXf red = indirect_of(result, 0, r);
  const Eigen::MatrixXf green = indirect_of(result, 1, r);
  const Eigen::MatrixXf blue = indirect_of(result, 2, r);
  return store_blocks(pack_blocks({&red, &green, &blue}), storage);
}

}  // namespace relight
