// The turn about the vertical (math/placement.h VerticalTurn): counter-clockwise seen from
// above, and its inverse undoes it with the same sine and cosine, as a turn by −rotate_deg.
#include <gtest/gtest.h>

#include "math/placement.h"

namespace relight {
namespace {

TEST(VerticalTurn, AQuarterTurnTakesXToMinusZAndItsInverseUndoesItTo1e12) {
  const VerticalTurn quarter(90);
  const Vec3 x = quarter({1, 0, 0});
  EXPECT_NEAR(x.x, 0, 1e-12);
  EXPECT_NEAR(x.z, -1, 1e-12);
  const Vec3 v{0.3, -0.7, 0.64};
  for (const double deg : {-170.0, -33.0, 0.0, 12.5, 90.0, 271.0}) {
    const VerticalTurn turn(deg);
    const Vec3 back = turn.inverse(turn(v));
    const Vec3 minus = VerticalTurn(-deg)(v), inverse = turn.inverse(v);
    EXPECT_NEAR(back.x, v.x, 1e-12) << deg;
    EXPECT_NEAR(back.y, v.y, 1e-12) << deg;
    EXPECT_NEAR(back.z, v.z, 1e-12) << deg;
    EXPECT_NEAR(inverse.x, minus.x, 1e-12) << deg;
    EXPECT_NEAR(inverse.z, minus.z, 1e-12) << deg;
  }
}

}  // namespace
}  // namespace relight
