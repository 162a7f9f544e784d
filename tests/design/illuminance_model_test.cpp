// The sensors' illuminance as a linear model of the dimmers (design/illuminance_model.h)
// against the relit scene.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "design/illuminance_model.h"
#include "design_room_fixture.h"

namespace relight {
namespace {

using testing::design_room;

// With daylight and a fixed luminaire in the base, the model of the two free ones reproduces
// the relit scene at random dimmers (colours and the IES distribution included) within 1e-5
// relative: everything the Relighter sums is linear in a luminaire's output.
TEST(IlluminanceModel, ReproducesTheRelitSceneAtRandomDimmersWithin1e5) {
  RelitScene relit(design_room().rlt, std::nullopt);
  const Scene& scene = relit.scene();
  LightingState base = default_lighting_state(scene);
  base.luminaires[0].color = {1.2, 1.0, 0.6};
  base.luminaires[1].dimmer = 0.4;  // "middle" fixed at 0.4
  const std::vector<std::size_t> free = {0, 2}, sets = {0, 1};
  const IlluminanceModel model = illuminance_model(relit, base, free, sets);
  ASSERT_EQ(model.rows(), scene.sensor_count());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1.5);
  for (int trial = 0; trial < 4; ++trial) {
    const std::vector<double> d = {u(rng), u(rng)};
    LightingState state = base;
    for (std::size_t k = 0; k < free.size(); ++k) state.luminaires[free[k]].dimmer = d[k];
    relit.apply(state);
    const std::vector<Rgb> e = relit.sensor_irradiance();
    for (std::size_t r = 0; r < model.rows(); ++r) {
      const double lux = luminance(e[r]);
      EXPECT_NEAR(model.lux(r, d), lux, 1e-5 * std::abs(lux) + 1e-6)
          << "row " << r << " trial " << trial;
    }
  }
  // The base includes the window's daylight and the fixed luminaire.
  EXPECT_GT(model.base[0], 1);
}

TEST(IlluminanceModel, AColumnIsTheLuminaireAloneAtFullOutput) {
  RelitScene relit(design_room().rlt, std::nullopt);
  LightingState base = default_lighting_state(relit.scene());
  for (PortalState& p : base.portals) p.tint = {0, 0, 0};
  const std::vector<std::size_t> free = {0, 1, 2}, sets = {1};
  const IlluminanceModel model = illuminance_model(relit, base, free, sets);
  ASSERT_EQ(model.rows(), 8U);
  LightingState alone = base;
  alone.luminaires[0].on = alone.luminaires[1].on = false;
  relit.apply(alone);
  const std::vector<Rgb> e = relit.sensor_irradiance();
  for (std::size_t r = 0; r < model.rows(); ++r) {
    const double lux = luminance(e[24 + r]);
    EXPECT_NEAR(model.column(r, 2), lux, 1e-5 * std::abs(lux) + 1e-6);
    EXPECT_NEAR(model.base[r], 0, 1e-6);  // dark windows, every luminaire free
  }
}

}  // namespace
}  // namespace relight
