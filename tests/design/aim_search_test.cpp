// Aims within cones and the compass search over them (design/aim_search.h).
#include <gtest/gtest.h>

#include <cmath>

#include "design/aim_search.h"

namespace relight {
namespace {

constexpr double kDeg = kPi / 180;

double angle_between(Vec3 a, Vec3 b) {
  return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0));
}

TEST(AimCone, AnOffsetsLengthIsItsAngleFromTheAxisAndRoundTrips) {
  const AimCone cone{normalize(Vec3{0.2, -1, 0.1}), 30 * kDeg};
  for (const AimOffset o :
       {AimOffset{0, 0}, AimOffset{0.3, 0}, AimOffset{-0.1, 0.25}, AimOffset{0.2, -0.2}}) {
    const Vec3 aim = aim_in_cone(cone, o);
    EXPECT_NEAR(length(aim), 1, 1e-12);
    EXPECT_NEAR(angle_between(aim, cone.axis), std::hypot(o[0], o[1]), 1e-9);
    const AimOffset back = offset_in_cone(cone, aim);
    EXPECT_NEAR(back[0], o[0], 1e-9);
    EXPECT_NEAR(back[1], o[1], 1e-9);
  }
}

TEST(AimCone, AnAimOutsideIsPulledOntoTheRim) {
  const AimCone cone{{0, -1, 0}, 20 * kDeg};
  const AimOffset o = offset_in_cone(cone, normalize(Vec3{1, -1, 0}));  // 45° off the axis
  EXPECT_NEAR(std::hypot(o[0], o[1]), 20 * kDeg, 1e-12);
  EXPECT_NEAR(angle_between(aim_in_cone(cone, o), Vec3{1, -1, 0}), 25 * kDeg, 1e-9);
}

// Two cones whose best aims are known: the search ends within its last step (a quarter
// degree) of each, and one whose best lies outside ends on the rim nearest to it.
TEST(AimSearch, FindsTheBestAimsOfASmoothScoreWithinAQuarterDegree) {
  const std::vector<AimCone> cones = {{{0, -1, 0}, 30 * kDeg}, {{0, -1, 0}, 10 * kDeg}};
  const Vec3 best[2] = {normalize(Vec3{0.2, -1, -0.15}), normalize(Vec3{0.6, -1, 0})};
  std::vector<AimOffset> offsets(2, AimOffset{0, 0});
  double score = 0;
  const auto total = [&](const std::vector<AimOffset>& o) {
    return angle_between(aim_in_cone(cones[0], o[0]), best[0]) +
           angle_between(aim_in_cone(cones[1], o[1]), best[1]);
  };
  score = total(offsets);
  const int trials = search_aims(cones, offsets, [&](std::size_t i, AimOffset o) {
    std::vector<AimOffset> t = offsets;
    t[i] = o;
    const double s = total(t);
    if (s >= score) return false;
    score = s;
    return true;
  });
  EXPECT_LT(trials, 400);
  EXPECT_LT(angle_between(aim_in_cone(cones[0], offsets[0]), best[0]), 0.25 * kDeg);
  // best[1] is 31° off the axis: the rim point toward it, 21° from it.
  EXPECT_NEAR(angle_between(aim_in_cone(cones[1], offsets[1]), best[1]),
              angle_between(best[1], cones[1].axis) - 10 * kDeg, 0.25 * kDeg);
}

}  // namespace
}  // namespace relight
