#include "runtime/window_view.h"

#include <algorithm>

#include "math/cubemap.h"

namespace relight {

Rgb window_view_radiance(const Shell& shell, Vec3 outward) {
  const int n = shell.face_size;
  if (n < 1 || shell.cubemap.size() != cubemap_texel_count(n)) return {};
  const std::vector<double>& solid_angle = cubemap_solid_angles(n);  // one face, j·N + i
  const std::size_t per_face = solid_angle.size();
  Rgb sum;
  double weight = 0;
  for (std::size_t i = 0; i < shell.cubemap.size(); ++i) {
    const Vec3 dir = cubemap_texel_direction(n, cubemap_texel_from_index(n, i));
    if (dot(dir, outward) <= 0) continue;
    Rgb l = shell.cubemap[i];
    if (shell.sun_in_shell && i == shell.sun_texel) {  // frost may have spread part of it
      const Rgb rest = l - shell.sun_radiance;
      l = {std::max(rest.r, 0.0), std::max(rest.g, 0.0), std::max(rest.b, 0.0)};
    }
    const double omega = solid_angle[i % per_face];
    sum = sum + l * omega;
    weight += omega;
  }
  return weight > 0 ? sum * (1.0 / weight) : Rgb{};
}

WindowView window_view(const Shell& shell, Vec3 centre, std::uint32_t portal,
                       std::span<const PortalSun> suns) {
  WindowView view{&shell, centre, std::nullopt, Rgb{}};
  for (const PortalSun& sun : suns) {
    if (sun.portal != portal || !(sun.disc.solid_angle > 0)) continue;
    // The illuminance facing the sun over the disc's solid angle: its uniform luminance (the
    // disc is 0.53° across, where cos α = 1 to 1e-5).
    view.sun = sun.disc;
    view.sun_luminance = sun.illuminance * (1.0 / sun.disc.solid_angle);
  }
  return view;
}

}  // namespace relight
