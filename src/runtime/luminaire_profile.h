// A luminaire's distribution as the studio draws it: its intensity along the C-planes and
// the SH approximation the transfer lights with (sources/luminaires/distribution_profile.h),
// loaded from the distribution a lighting state names.
#pragma once

#include "scene/distribution_spec.h"
#include "sources/luminaires/distribution_profile.h"

namespace relight {

// `sh_order`: the transfer's (TransferView::sh_order); `samples` per curve. Throws
// InputError for a distribution file that cannot be read.
DistributionProfile luminaire_profile(const DistributionSpec& spec, int sh_order, int samples);

}  // namespace relight
