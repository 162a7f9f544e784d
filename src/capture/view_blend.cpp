#include "capture/view_blend.h"

#include <algorithm>
#include <cmath>

#include "math/vec3.h"

namespace relight {

namespace {

constexpr double kDeg = kPi / 180;
constexpr double kBin = 0.25 * kDeg;
constexpr double kBlend = 2 * kDeg;

double smoothstep(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

double clean_limit(const ViewMap& view, const ViewMap& other, double half_fov) {
  const double start = half_fov - 15 * kDeg;
  const int bins = static_cast<int>(std::ceil((half_fov - start) / kBin));
  std::vector<std::vector<float>> ratios(static_cast<std::size_t>(bins));
  for (std::size_t t = 0; t < view.radiance.size(); ++t) {
    if (!view.seen[t] || !other.seen[t] || view.clipped[t] || other.clipped[t]) continue;
    const double a = luminance(view.radiance[t]), b = luminance(other.radiance[t]);
    if (!(a > 0) || !(b > 0) || view.theta[t] < start) continue;
    const int bin = std::min(bins - 1, static_cast<int>((view.theta[t] - start) / kBin));
    ratios[static_cast<std::size_t>(bin)].push_back(static_cast<float>(std::log(a / b)));
  }
  const double darker = std::log(0.8);
  int inner = bins;  // the innermost ring of the band
  for (int bin = bins - 1; bin >= 0; --bin) {
    auto& r = ratios[static_cast<std::size_t>(bin)];
    if (r.size() < 16) {
      if (inner == bins) continue;  // the rim's last rings: too few texels to judge
      break;
    }
    std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
    if (r[r.size() / 2] >= darker) break;
    inner = bin;
  }
  if (inner == bins) return half_fov;
  return start + inner * kBin - 0.5 * kDeg;
}

BlendedMap blend_views(const ViewMap& front, double front_limit, const ViewMap& back,
                       double back_limit) {
  const std::size_t count = front.radiance.size();
  BlendedMap map{front.width, front.height, std::vector<Rgb>(count),
                 std::vector<std::uint8_t>(count, 0), std::vector<std::uint8_t>(count, 0)};
  const double disagree = std::log(1.5);
  for (std::size_t t = 0; t < count; ++t) {
    double wf = front.seen[t] ? smoothstep((front_limit - front.theta[t]) / kBlend) : 0;
    double wb = back.seen[t] ? smoothstep((back_limit - back.theta[t]) / kBlend) : 0;
    if (wf > 0 && wb > 0) {
      const double yf = luminance(front.radiance[t]), yb = luminance(back.radiance[t]);
      if (yf > 0 && yb > 0 && std::abs(std::log(yf / yb)) > disagree) {
        (front.theta[t] < back.theta[t] ? wb : wf) = 0;
      }
    }
    if (wf + wb <= 0) {
      map.hole[t] = 1;
      continue;
    }
    map.radiance[t] = (front.radiance[t] * wf + back.radiance[t] * wb) / (wf + wb);
    map.clipped[t] = ((wf > 0 && front.clipped[t]) || (wb > 0 && back.clipped[t])) ? 1 : 0;
  }
  return map;
}

}  // namespace relight
