// runtime/window_view.h: the glass of a window shows the mean radiance of its shell over the
// outward hemisphere, without the sun's deposit; per direction, the shell and the sun traced
// through that portal, its disc's luminance its illuminance over its solid angle.
#include <gtest/gtest.h>

#include "math/cubemap.h"
#include "runtime/window_view.h"

namespace relight {
namespace {

TEST(WindowView, MeanOverTheOutwardHemisphereWeightedBySolidAngle) {
  const int n = 16;
  Shell shell;
  shell.face_size = n;
  shell.cubemap.resize(cubemap_texel_count(n));
  // 100 cd/m² above the horizon, 20 below, 1e6 behind the window (must not count).
  const Vec3 outward{0, 0, 1};
  for (std::size_t i = 0; i < shell.cubemap.size(); ++i) {
    const Vec3 d = cubemap_texel_direction(n, cubemap_texel_from_index(n, i));
    const double l = dot(d, outward) <= 0 ? 1e6 : (d.y > 0 ? 100 : 20);
    shell.cubemap[i] = {l, l, l};
  }
  const Rgb mean = window_view_radiance(shell, outward);
  EXPECT_NEAR(mean.r, 60, 0.5);  // half the hemisphere each (texel rows straddle nothing)
  // The sun's deposit is removed from its texel.
  std::size_t sun = 0;
  for (std::size_t i = 0; i < shell.cubemap.size(); ++i) {
    const Vec3 d = cubemap_texel_direction(n, cubemap_texel_from_index(n, i));
    if (dot(d, outward) > 0.9 && d.y > 0) sun = i;
  }
  shell.sun_in_shell = true;
  shell.sun_texel = sun;
  shell.sun_radiance = {5e6, 5e6, 5e6};
  shell.cubemap[sun] = shell.cubemap[sun] + shell.sun_radiance;
  EXPECT_NEAR(window_view_radiance(shell, outward).r, mean.r, 1e-9);
}

TEST(WindowView, EmptyShellShowsBlack) {
  EXPECT_EQ(window_view_radiance(Shell{}, {0, 0, 1}).r, 0);
}

TEST(WindowView, TheSunTracedThroughThePortalIsItsDiscAtIlluminanceOverSolidAngle) {
  Shell shell;
  const SunDisc disc = make_sun_disc(normalize(Vec3{0.3, 0.8, -0.5}), 80000);
  const std::vector<PortalSun> suns{make_portal_sun(1, disc, Rgb{60000, 50000, 40000}, nullptr)};
  const WindowView through = window_view(shell, {1, 2, 3}, 1, suns);
  ASSERT_TRUE(through.sun.has_value());
  EXPECT_EQ(through.shell, &shell);
  EXPECT_NEAR(through.centre.y, 2, 0);
  EXPECT_NEAR(dot(through.sun->direction, disc.direction), 1, 1e-12);
  EXPECT_NEAR(through.sun_luminance.r * disc.solid_angle, 60000, 1e-6);
  EXPECT_NEAR(through.sun_luminance.b * disc.solid_angle, 40000, 1e-6);
  // Another portal's sun is not this one's.
  const WindowView other = window_view(shell, {0, 0, 0}, 0, suns);
  EXPECT_FALSE(other.sun.has_value());
  EXPECT_EQ(other.sun_luminance.g, 0);
}

}  // namespace
}  // namespace relight
