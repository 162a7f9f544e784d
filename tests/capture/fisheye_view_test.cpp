// Fisheye geometry (capture/fisheye_view.h): the three lens mappings and their inverses, the
// front and back views' orientation in the world, and photo point ↔ direction round trips.
#include "capture/fisheye_view.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relight {
namespace {

constexpr double kDeg = kPi / 180;

TEST(FisheyeView, EachLensMappingIsZeroAtTheCentreOneAtHalfTheFieldAndInvertsTo1e12) {
  for (const auto projection : {FisheyeProjection::kEquidistant, FisheyeProjection::kEquisolid,
                                FisheyeProjection::kStereographic}) {
    const FisheyeLens lens{projection, 190 * kDeg};
    EXPECT_NEAR(lens_radius(lens, 0), 0, 1e-15);
    EXPECT_NEAR(lens_radius(lens, 95 * kDeg), 1, 1e-12);
    for (double theta = 0; theta <= 95 * kDeg; theta += 5 * kDeg) {
      EXPECT_NEAR(lens_angle(lens, lens_radius(lens, theta)), theta, 1e-12);
    }
  }
  // Equidistant: r is proportional to θ.
  const FisheyeLens equidistant{FisheyeProjection::kEquidistant, 180 * kDeg};
  EXPECT_NEAR(lens_radius(equidistant, 45 * kDeg), 0.5, 1e-12);
  // Equisolid: r = 2 f sin(θ/2), so at 60° of a 180° lens r = sin 30° / sin 45°.
  const FisheyeLens equisolid{FisheyeProjection::kEquisolid, 180 * kDeg};
  EXPECT_NEAR(lens_radius(equisolid, 60 * kDeg), std::sin(30 * kDeg) / std::sin(45 * kDeg), 1e-12);
}

TEST(FisheyeView, TheFrontLooksNorthWithEastToItsRightAndTheBackSouthWithWestToItsRight) {
  const ImageCircle circle{500, 400, 300};
  const FisheyeLens lens{FisheyeProjection::kEquidistant, 180 * kDeg};
  const FisheyeView front = front_view(circle, lens), back = back_view(circle, lens);
  const auto expect_dir = [](std::optional<Vec3> d, Vec3 want) {
    ASSERT_TRUE(d);
    EXPECT_NEAR(d->x, want.x, 1e-12);
    EXPECT_NEAR(d->y, want.y, 1e-12);
    EXPECT_NEAR(d->z, want.z, 1e-12);
  };
  expect_dir(view_direction(front, {500, 400}), {0, 0, -1});
  expect_dir(view_direction(front, {800, 400}), {1, 0, 0});  // right edge: east
  expect_dir(view_direction(front, {500, 100}), {0, 1, 0});  // top edge: up
  expect_dir(view_direction(back, {500, 400}), {0, 0, 1});
  expect_dir(view_direction(back, {800, 400}), {-1, 0, 0});  // right edge: west
  expect_dir(view_direction(back, {500, 700}), {0, -1, 0});  // bottom edge: down
  EXPECT_FALSE(view_direction(front, {500, 99}));            // outside the circle
  EXPECT_FALSE(photo_point(front, {0, 0, 1}));               // behind a 180° lens
}

TEST(FisheyeView, PhotoPointAndViewDirectionAreInversesTo1e9Pixels) {
  const ImageCircle circle{612.3, 401.7, 433.2};
  for (const auto projection : {FisheyeProjection::kEquidistant, FisheyeProjection::kEquisolid,
                                FisheyeProjection::kStereographic}) {
    const FisheyeView view = back_view(circle, {projection, 190 * kDeg});
    for (double x = 250; x < 1000; x += 37.5) {
      for (double y = 50; y < 800; y += 41.25) {
        const std::optional<Vec3> d = view_direction(view, {x, y});
        if (!d) continue;
        const std::optional<PhotoPoint> p = photo_point(view, *d);
        ASSERT_TRUE(p);
        EXPECT_NEAR(p->x, x, 1e-9);
        EXPECT_NEAR(p->y, y, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace relight
