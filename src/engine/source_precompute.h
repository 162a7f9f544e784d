// What a source module gives the precompute driver (docs/architecture.md, "Where the next
// thing goes"): it registers the columns it bounces, computes its direct transfer (writing
// the direct irradiance of each registered column, and keeping whatever else it stores, e.g.
// exact-direct geometry or cubemaps), and takes its interreflected columns after the one
// bounce solve that all sources share. precompute_sources() runs them in order.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/bounce_solver.h"
#include "engine/column_registry.h"
#include "engine/gather_operator.h"
#include "engine/ranks.h"
#include "engine/receivers.h"
#include "scene/mesh_preparation.h"
#include "trace/traced_scene.h"

namespace relight {

struct PhaseTiming {
  std::string name;
  double seconds = 0;
  std::uint64_t rays = 0;
  // Of `seconds`, in exchanges with other ranks, waiting for them included (engine/ranks.h),
  // and the bytes received from them.
  double exchange_seconds = 0;
  std::uint64_t exchange_bytes = 0;
};

// What the ranks' exchanges cost between its making and take(): seconds and bytes received.
class ExchangeMeter {
 public:
  explicit ExchangeMeter(const RankShares* ranks)
      : exchange_(ranks != nullptr ? ranks->exchange : nullptr),
        seconds_(exchange_ != nullptr ? exchange_->exchange_seconds() : 0),
        bytes_(exchange_ != nullptr ? exchange_->exchange_bytes() : 0) {}
  // Sets the phase's exchange_seconds and exchange_bytes.
  void take(PhaseTiming& phase) const {
    if (exchange_ == nullptr) return;
    phase.exchange_seconds = exchange_->exchange_seconds() - seconds_;
    phase.exchange_bytes = exchange_->exchange_bytes() - bytes_;
  }

 private:
  const RankExchange* exchange_;
  double seconds_;
  std::uint64_t bytes_;
};

// What every source's direct transfer sees: the receivers, where their rays start, the
// prepared mesh and its Embree scenes, and the ranks of the precompute (engine/ranks.h): a
// source traces its per-receiver work for its own share; the direct columns keep each rank's
// own rows (DirectColumns::set), and what else a source keeps it exchanges or not as its file
// sections need (the packed transfer stays with its rank until rank 0 writes it).
struct SourceContext {
  const Receivers& receivers;
  const std::vector<Vec3>& ray_points;  // engine/receivers.h receiver_ray_points
  const PreparedMesh& mesh;
  const TracedScene& traced;
  bool progress = true;
  const RankShares* ranks = nullptr;  // nullptr: this process alone
};

class SourcePrecompute {
 public:
  virtual ~SourcePrecompute() = default;
  // Adds a range per bounced basis set to `registry` (none for a source that does not bounce).
  virtual void register_columns(ColumnRegistry& registry) = 0;
  // The direct transfer: fills the direct irradiance of its ranges. Returns its phase
  // timing, or an empty name for none.
  virtual PhaseTiming compute_direct(const SourceContext& context, DirectColumns& columns) = 0;
  // Takes the interreflected light of its ranges.
  virtual void take_indirect(const BounceResult& result) = 0;
};

struct SourcesResult {
  int bounces = 0;
  std::vector<PhaseTiming> phases;  // each source's direct phase, "bounces", "pack"
};

// Registers every source's columns, computes their direct transfer in order, bounces all
// columns through `gather` together, and hands each source its interreflected columns.
SourcesResult precompute_sources(const SourceContext& context, const GatherOperator& gather,
                                 const BounceSettings& bounce,
                                 std::span<SourcePrecompute* const> sources);

}  // namespace relight
