#include "sources/luminaires/distribution_profile.h"

#include <cmath>
#include <stdexcept>

#include "math/sh.h"
#include "math/zonal.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {

namespace {

// The projection's order² coefficients in the right-handed luminaire frame (zonal ones
// expanded about +z = the aim).
std::vector<double> local_coefficients(const Distribution& distribution, int order,
                                       ShWindow window) {
  LuminaireShSettings settings;
  settings.order = order;
  settings.window = window;
  const LocalLuminaireSh local = project_luminaire_local(distribution, settings);
  return local.zonal ? zonal_rotate(local.coeffs, Vec3{0, 0, 1}) : local.coeffs;
}

}  // namespace

DistributionProfile distribution_profile(const Distribution& distribution, int order,
                                         ShWindow window, int samples) {
  if (samples < 2) throw std::invalid_argument("distribution profile: samples must be >= 2");
  if (order < 1) throw std::invalid_argument("distribution profile: order must be >= 1");
  const std::vector<double> plain = local_coefficients(distribution, order, ShWindow::kNone);
  const std::vector<double> windowed = local_coefficients(distribution, order, window);
  DistributionProfile p;
  p.flux_lm = distribution.flux_lm();
  for (int i = 0; i < samples; ++i) p.gamma_deg.push_back(180.0 * i / (samples - 1));
  for (std::size_t plane = 0; plane < kProfilePlanesDeg.size(); ++plane) {
    const double c = radians(kProfilePlanesDeg[plane]);
    for (const double gamma_deg : p.gamma_deg) {
      const double g = radians(gamma_deg);
      // Photometric frame (x = C0, y = C90, z = aim); the SH frame has y = −C90
      // (sources/luminaires/luminaire_sh.h, "Handedness").
      const Vec3 local{std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), std::cos(g)};
      const Vec3 sh_dir{local.x, -local.y, local.z};
      p.exact[plane].push_back(distribution.intensity(local));
      p.sh[plane].push_back(sh_evaluate(plain, sh_dir));
      p.sh_windowed[plane].push_back(sh_evaluate(windowed, sh_dir));
    }
  }
  return p;
}

}  // namespace relight
