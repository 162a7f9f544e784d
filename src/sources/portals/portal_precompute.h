// The portals' precompute (Yue et al. 2009 §4.1): per portal the direct cubemap of every
// receiver (§4.1.2), and the response to each SH basis radiance Y_k (l < portal_sh_order) of
// its shell — its direct irradiance as bounced columns, its interreflection (§4.1.1, here
// through the shared gather operator) taken back after the bounce solve.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/source_precompute.h"
#include "engine/transfer_blocks.h"
#include "scene/scene.h"
#include "sources/portals/portal_direct.h"
#include "sources/portals/portal_geometry.h"

namespace relight {

struct PortalTransfer {
  PortalGeometry geometry;
  PortalDirect direct;      // direct.sh_columns is emptied once registered
  PackedTransfer indirect;  // RGB, sh_order² bases, blocked (transfer_blocks.h)
};

class PortalPrecompute : public SourcePrecompute {
 public:
  PortalPrecompute(const Scene& scene, std::uint64_t seed);
  void register_columns(ColumnRegistry& registry) override;
  PhaseTiming compute_direct(const SourceContext& context, DirectColumns& columns) override;
  void take_indirect(const BounceResult& result) override;

  std::vector<PortalTransfer> transfers;  // in scene order
  std::vector<std::string> warnings;      // portals too large for their shells (§6)

 private:
  const Scene* scene_;
  std::uint64_t seed_;
  std::vector<ColumnRange> columns_;
};

}  // namespace relight
