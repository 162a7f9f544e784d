#include "reference/reference_mirror.h"

#include <algorithm>
#include <cmath>

#include "math/frame.h"

namespace relight {

namespace {

// The narrowest lobe drawn (rad): α is clamped at 1e-4 by the BRDF, a slope of 1e-4 is
// still far finer than any receiver.
constexpr double kMinWidth = 1e-5;

}  // namespace

std::optional<MirrorLobe> mirror_lobe(const MirrorPlane& plane, double alpha, Vec3 x, Vec3 light) {
  const double hx = plane.height(x), hl = plane.height(light);
  if (hx <= 1e-6 || hl <= 1e-6) return std::nullopt;
  const Vec3 unfolded = plane.image(light) - x;
  const double d = length(unfolded);
  if (!(d > 0)) return std::nullopt;
  // y0 divides the unfolded path in the ratio of the heights.
  const double s_x = d * hx / (hx + hl), s_light = d - s_x;
  const Frame frame = frame_from_normal(unfolded / d);
  MirrorLobe lobe{frame.to_world({0, 0, 1}), frame.to_world({1, 0, 0}), frame.to_world({0, 1, 0}),
                  0};
  lobe.width = std::max(2 * alpha * s_light / (s_x + s_light), kMinWidth);
  return lobe;
}

std::optional<MirrorLobe> mirror_sun_lobe(const MirrorPlane& plane, double alpha, Vec3 x,
                                          Vec3 toward, double radius) {
  const double cos_in = dot(plane.normal, toward);
  if (plane.height(x) <= 1e-6 || cos_in <= 0) return std::nullopt;
  const Frame frame = frame_from_normal(normalize(toward - plane.normal * (2 * cos_in)));
  return MirrorLobe{frame.n, frame.t, frame.b, std::max(2 * alpha + radius, kMinWidth)};
}

Vec3 sample_mirror_lobe(const MirrorLobe& lobe, double u1, double u2) {
  // |s|² = β² u / (1 − u): the inverse of P(|s| < r) = r² / (β² + r²).
  const double u = std::min(u1, 1 - 1e-12);
  const double r = lobe.width * std::sqrt(u / (1 - u));
  const double phi = 2 * kPi * u2;
  return normalize(lobe.axis + lobe.t1 * (r * std::cos(phi)) + lobe.t2 * (r * std::sin(phi)));
}

double mirror_lobe_pdf(const MirrorLobe& lobe, Vec3 w) {
  const double c = dot(w, lobe.axis);
  if (c <= 0) return 0;
  const double sx = dot(w, lobe.t1) / c, sy = dot(w, lobe.t2) / c;
  const double s2 = (sx * sx + sy * sy) / (lobe.width * lobe.width);
  const double p_s = 1 / (kPi * lobe.width * lobe.width * (1 + s2) * (1 + s2));
  return p_s / (c * c * c);
}

}  // namespace relight
