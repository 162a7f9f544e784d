// Glazing transmittance (math/glazing.h) against the Fresnel slab sums evaluated by hand (a
// separate script of the formulas in glazing.h), to 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "math/glazing.h"

namespace relight {
namespace {

double at_degrees(const Glazing& g, double deg) {
  return glazing_transmittance(g, std::cos(deg * 3.14159265358979323846 / 180));
}

TEST(Glazing, ClearPanesTransmitAtMostTheFresnelLimit) {
  // One pane: (1 − r)/(1 + r), r = (0.52/2.52)² = 0.042580.
  EXPECT_NEAR(max_glazing_transmittance(1), 0.918318, 1e-6);
  EXPECT_NEAR(max_glazing_transmittance(2), 0.848972, 1e-6);
  EXPECT_NEAR(max_glazing_transmittance(3), 0.789364, 1e-6);
}

TEST(Glazing, SingleAndDoublePanesFollowTheSlabSumsAtEveryIncidence) {
  const Glazing single = make_glazing(0.88, 1, false);
  EXPECT_NEAR(at_degrees(single, 0), 0.88, 1e-9);
  EXPECT_NEAR(at_degrees(single, 30), 0.875508, 1e-5);
  EXPECT_NEAR(at_degrees(single, 45), 0.859903, 1e-5);
  EXPECT_NEAR(at_degrees(single, 60), 0.799868, 1e-5);
  EXPECT_NEAR(at_degrees(single, 75), 0.577396, 1e-5);  // 0.656 of the normal value
  EXPECT_NEAR(at_degrees(single, 80), 0.423546, 1e-5);
  EXPECT_NEAR(single.pane_internal_transmittance, 0.958415, 1e-5);
  const Glazing dbl = make_glazing(0.78, 2, false);
  EXPECT_NEAR(at_degrees(dbl, 0), 0.78, 1e-9);
  EXPECT_NEAR(at_degrees(dbl, 30), 0.773739, 1e-5);
  EXPECT_NEAR(at_degrees(dbl, 60), 0.682902, 1e-5);
  EXPECT_NEAR(at_degrees(dbl, 75), 0.413639, 1e-5);
  EXPECT_NEAR(at_degrees(dbl, 80), 0.261802, 1e-5);
  // Nothing at grazing incidence or from behind.
  EXPECT_EQ(glazing_transmittance(single, 0), 0);
  EXPECT_EQ(glazing_transmittance(single, -0.5), 0);
}

TEST(Glazing, RefusesPanesAndTransmittancesGlassCannotHave) {
  EXPECT_THROW(make_glazing(0.95, 1, false), std::invalid_argument);
  EXPECT_THROW(make_glazing(0.85, 2, false), std::invalid_argument);
  EXPECT_THROW(make_glazing(0, 1, false), std::invalid_argument);
  EXPECT_THROW(make_glazing(0.5, 4, false), std::invalid_argument);
  EXPECT_NO_THROW(make_glazing(max_glazing_transmittance(3), 3, false));
}

}  // namespace
}  // namespace relight
