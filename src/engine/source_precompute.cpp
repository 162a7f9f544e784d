#include "engine/source_precompute.h"

#include <chrono>

#include "engine/transfer_blocks.h"

namespace relight {

SourcesResult precompute_sources(const SourceContext& context, const GatherOperator& gather,
                                 const BounceSettings& bounce,
                                 std::span<SourcePrecompute* const> sources) {
  ColumnRegistry registry;
  for (SourcePrecompute* s : sources) s->register_columns(registry);
  const RankShares ranks = context.ranks != nullptr
                               ? *context.ranks
                               : single_process_shares(context.receivers.size(), kBlock);
  DirectColumns columns(ranks, registry);
  SourcesResult out;
  for (SourcePrecompute* s : sources) {
    const ExchangeMeter meter(context.ranks);
    PhaseTiming t = s->compute_direct(context, columns);
    meter.take(t);
    if (!t.name.empty()) out.phases.push_back(std::move(t));
  }
  const ExchangeMeter meter(context.ranks);
  const BounceResult result = solve_bounces(gather, context.receivers, columns.matrix(), bounce,
                                            context.progress, context.ranks);
  out.bounces = result.bounces;
  out.phases.push_back({"bounces", result.seconds, 0});
  meter.take(out.phases.back());
  const auto start = std::chrono::steady_clock::now();
  for (SourcePrecompute* s : sources) s->take_indirect(result);
  const std::chrono::duration<double> pack = std::chrono::steady_clock::now() - start;
  out.phases.push_back({"pack", pack.count(), 0});
  return out;
}

}  // namespace relight
