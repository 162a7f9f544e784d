#include "runtime/luminaire_profile.h"

#include "light/distribution.h"
#include "math/sh_window.h"

namespace relight {

DistributionProfile luminaire_profile(const DistributionSpec& spec, int sh_order, int samples) {
  return distribution_profile(load_distribution(spec), sh_order, ShWindow::kSigma, samples);
}

}  // namespace relight
