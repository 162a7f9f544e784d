#include "light/emitter_placement.h"

#include <stdexcept>

#include "math/placement.h"

namespace relight {

PlacedEmitters place_emitters(const std::vector<Emitter>& emitters,
                              const std::vector<EmitterState>& states) {
  if (emitters.size() != states.size()) {
    throw std::invalid_argument("place_emitters: one state per emitter");
  }
  PlacedEmitters out;
  for (std::size_t e = 0; e < emitters.size(); ++e) {
    const Emitter& emitter = emitters[e];
    const EmitterState& s = states[e];
    out.radiance.push_back(s.color * (s.on ? s.luminance : 0.0));
    if (!s.on || s.luminance <= 0) continue;
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    for (const Vec3& p : emitter.geometry.positions) {
      out.positions.push_back(placed_point(p, emitter.pivot, s));
    }
    for (const Triangle& t : emitter.geometry.triangles) {
      const Triangle placed{t[0] + first, t[1] + first, t[2] + first};
      out.triangles.push_back(placed);
      out.emitter_of_triangle.push_back(static_cast<std::uint32_t>(e));
      const Vec3 a = out.positions[placed[0]];
      const Vec3 n = cross(out.positions[placed[1]] - a, out.positions[placed[2]] - a);
      out.normals.push_back(length(n) > 0 ? normalize(n) : Vec3{0, 0, 0});
      out.triangle_radiance.push_back(out.radiance.back());
    }
  }
  return out;
}

}  // namespace relight
