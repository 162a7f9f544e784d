#include "design/aim_search.h"

#include <algorithm>
#include <cmath>

#include "math/frame.h"

namespace relight {

namespace {

AimOffset clipped(const AimCone& cone, AimOffset o) {
  const double r = std::hypot(o[0], o[1]);
  if (r <= cone.radius_rad) return o;
  const double s = cone.radius_rad / r;
  return {o[0] * s, o[1] * s};
}

}  // namespace

Vec3 aim_in_cone(const AimCone& cone, AimOffset offset) {
  const double angle = std::hypot(offset[0], offset[1]);
  if (angle == 0) return cone.axis;
  const Frame f = frame_from_normal(cone.axis);
  const Vec3 along = normalize(f.t * offset[0] + f.b * offset[1]);
  return normalize(cone.axis * std::cos(angle) + along * std::sin(angle));
}

AimOffset offset_in_cone(const AimCone& cone, Vec3 aim) {
  const Frame f = frame_from_normal(cone.axis);
  const Vec3 local = f.to_local(normalize(aim));
  const double sideways = std::hypot(local.x, local.y);
  if (sideways < 1e-12) return {0, 0};
  const double angle = std::atan2(sideways, local.z);
  return clipped(cone, {local.x / sideways * angle, local.y / sideways * angle});
}

int search_aims(std::span<const AimCone> cones, std::vector<AimOffset>& offsets,
                const std::function<bool(std::size_t, AimOffset)>& try_offset,
                const AimSearchSettings& settings) {
  std::vector<double> step(cones.size());
  for (std::size_t i = 0; i < cones.size(); ++i) {
    step[i] = settings.first_step_fraction * cones[i].radius_rad;
  }
  int trials = 0;
  const AimOffset moves[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (;;) {
    bool searching = false;
    for (std::size_t i = 0; i < cones.size(); ++i) {
      if (step[i] < settings.last_step_rad) continue;
      searching = true;
      bool improved = false;
      for (const AimOffset& m : moves) {
        if (trials >= settings.max_trials) return trials;
        const AimOffset o = offsets[i];
        const AimOffset candidate =
            clipped(cones[i], {o[0] + m[0] * step[i], o[1] + m[1] * step[i]});
        if (std::hypot(candidate[0] - o[0], candidate[1] - o[1]) < 1e-12) continue;
        ++trials;
        if (try_offset(i, candidate)) {
          offsets[i] = candidate;
          improved = true;
          break;
        }
      }
      if (!improved) step[i] *= 0.5;
    }
    if (!searching) return trials;
  }
}

}  // namespace relight
