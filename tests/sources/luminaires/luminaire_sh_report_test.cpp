// Inputs of the "direct": "sh" error table (Dobashi et al. 1995's own direct light,
// Dobashi et al. 1995 Eq. 15 with the distribution replaced by its windowed SH series,
// Eq. 18): a cosine-power spot (1000 cd, exponent 10, cut-off 60°) 3 m above a floor and
// aimed 30° off nadir, illuminance E = I(ω) cosθ / r² on a 16 m × 16 m grid, exact vs the
// SH series at several orders and windows. Prints the table; asserts only what must hold
// (the error falls with the order, the window removes most negative illuminance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "light/luminaire_frame.h"
#include "math/sh.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {
namespace {

struct DirectError {
  double max_rel = 0;  // max |E_sh − E| / max E
  double rms_rel = 0;  // rms(E_sh − E) / rms(E)
  double min_lux = 0;  // most negative E_sh
};

DirectError direct_error(const PlacedLuminaire& lum, const std::vector<double>& w) {
  const double height = lum.position.y;
  double max_e = 0, max_err = 0, sum_e2 = 0, sum_err2 = 0, min_sh = 0;
  for (double x = -8; x <= 8 + 1e-9; x += 0.25) {
    for (double z = -8; z <= 8 + 1e-9; z += 0.25) {
      const Vec3 v = Vec3{x, 0, z} - lum.position;
      const double r = length(v);
      const Vec3 d = v / r;
      const double g = height / (r * r * r);  // cosθ / r² with cosθ = height / r
      const double exact = lum.distribution.intensity(lum.frame.to_photometric(d)) * g;
      const double sh = sh_evaluate(w, d) * g;
      max_e = std::max(max_e, exact);
      max_err = std::max(max_err, std::abs(sh - exact));
      sum_e2 += exact * exact;
      sum_err2 += (sh - exact) * (sh - exact);
      min_sh = std::min(min_sh, sh);
    }
  }
  return {max_err / max_e, std::sqrt(sum_err2 / sum_e2), min_sh};
}

TEST(LuminaireShReport, DirectShErrorOfATiltedSpotOnAFloor) {
  const Distribution spot{CosinePowerModel{1000.0, 10.0, radians(60.0)}};
  const Vec3 aim{std::sin(radians(30.0)), -std::cos(radians(30.0)), 0};
  const Vec3 c0{std::cos(radians(30.0)), std::sin(radians(30.0)), 0};
  const PlacedLuminaire lum{{0, 3, 0}, photometric_frame(aim, c0), Rgb{1, 1, 1}, spot};

  std::printf("direct: sh, cos^10 cut 60°, 1000 cd, 3 m, 30° off nadir (65×65 floor grid)\n");
  std::printf("%6s %-8s %10s %10s %12s\n", "order", "window", "max/maxE", "rms/rmsE", "min E (lx)");
  DirectError none4, none16, sigma8, none8;
  for (const int order : {4, 8, 12, 16}) {
    for (const ShWindow window : {ShWindow::kNone, ShWindow::kSigma, ShWindow::kHanning}) {
      const auto w = luminaire_world_sh(spot, aim, c0, {.order = order, .window = window});
      const DirectError e = direct_error(lum, w);
      const char* name = window == ShWindow::kNone    ? "none"
                         : window == ShWindow::kSigma ? "sigma"
                                                      : "hanning";
      std::printf("%6d %-8s %10.4f %10.4f %12.3f\n", order, name, e.max_rel, e.rms_rel, e.min_lux);
      RecordProperty("order" + std::to_string(order) + "_" + name + "_rms_rel",
                     std::to_string(e.rms_rel));
      if (window == ShWindow::kNone && order == 4) none4 = e;
      if (window == ShWindow::kNone && order == 8) none8 = e;
      if (window == ShWindow::kNone && order == 16) none16 = e;
      if (window == ShWindow::kSigma && order == 8) sigma8 = e;
    }
  }
  EXPECT_LT(none16.rms_rel, none4.rms_rel);
  EXPECT_GT(sigma8.min_lux, none8.min_lux);
}

}  // namespace
}  // namespace relight
