// The bounce solver's columns: every source that bounces light through the one gather operator asks
// the registry for a range of columns, one per basis function of each of its instances (a
// luminaire's K SH bases, a portal's shell bases, the emitters' shadowed-transfer bases). The
// registry hands the ranges out in order and is the only place that knows where a source's columns
// lie; sources read and write their columns through their ranges (DirectColumns::of, indirect_of).
// Pinned by tests/engine/column_registry_test.cpp.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/bounce_solver.h"
#include "engine/ranks.h"
#include "engine/transfer_blocks.h"

namespace relight {

struct ColumnRange {
  Eigen::Index first = 0;
  Eigen::Index count = 0;
};

class ColumnRegistry {
 public:
  // A new range of `count` columns after every range handed out so far; `owner` names it
  // in messages ("luminaire 2", "portal south").
  ColumnRange add(std::string owner, Eigen::Index count);
  Eigen::Index columns() const { return columns_; }
  const std::vector<std::string>& owners() const { return owners_; }

 private:
  Eigen::Index columns_ = 0;
  std::vector<std::string> owners_;
};

// The direct irradiance of every registered column, receivers × columns (scalar: direct light is
// stored as geometry only, and albedo colours the bounced light). On one of several ranks
// (engine/ranks.h), the rows of its receivers only, as its local rows.
class DirectColumns {
 public:
  DirectColumns(const RankShares& ranks, const ColumnRegistry& registry)
      : ranks_(ranks),
        matrix_(static_cast<Eigen::Index>(ranks.my_receivers()), registry.columns()) {}
  // This rank's rows of a range, as its local rows.
  auto of(ColumnRange r) { return matrix_.middleCols(r.first, r.count); }
  // Sets a range from every receiver's rows (receivers × r.count), keeping this rank's.
  void set(ColumnRange r, const Eigen::MatrixXf& every_receiver);
  const Eigen::MatrixXf& matrix() const { return matrix_; }

 private:
  RankShares ranks_;
  Eigen::MatrixXf matrix_;
};

// A range's interreflected columns of one colour channel (0 r, 1 g, 2 b), receivers × count.
inline auto indirect_of(const BounceResult& result, int channel, ColumnRange r) {
  return result.indirect[static_cast<std::size_t>(channel)].middleCols(r.first, r.count);
}

// A range's interreflected columns packed in the blocked RGB layout and stored as `storage`
// (engine/transfer_blocks.h). On one of several ranks (collective), its blocks only, binary16
// scaled by the ranks' largest value so that every rank's blocks share the section's scale.
PackedTransfer pack_indirect_blocks(const BounceResult& result, ColumnRange r,
                                    TransferStorage storage);

}  // namespace relight
