// `relight annual` relights streams of hours at once, each by its own twin of the opened scene
// (runtime/annual_daylight.h, RelitScene::twin):
//  * a twin shares the sensors' importance (the same object, not solved again) and reads the
//    same sensor values as the scene it was made from, exactly;
//  * a year's values are the same, exactly, whether one stream or two relit its hours.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <memory>

#include "runtime/annual_daylight.h"
#include "support/daylight_room.h"
#include "support/precomputed_file.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

struct SpringRoom {
  testing::TempDir dir;
  std::filesystem::path rlt =
      testing::write_precomputed(dir, "room", testing::south_window_room(0.8));
  AnnualHours hours;
  SpringRoom() {
    testing::SyntheticPlace place;
    place.first_month = 4;  // April: 30 days of overcast, clear and intermediate skies
    place.last_month = 4;
    hours = annual_hours(parse_epw(testing::synthetic_epw(place), "april.epw"), {}, 0);
  }
};

const SpringRoom& spring_room() {
  static const SpringRoom room;
  return room;
}

TEST(AnnualStreams, ATwinSharesTheImportanceAndReadsTheSameSensors) {
  const SpringRoom& room = spring_room();
  const std::unique_ptr<RelitScene> relit = open_for_annual(room.rlt);
  ASSERT_NE(relit->relighter().sensor_importance(), nullptr);
  const std::unique_ptr<RelitScene> twin = relit->twin();
  EXPECT_EQ(twin->relighter().sensor_importance(), relit->relighter().sensor_importance());
  LightingState state = daylight_alone(relit->state());
  ASSERT_GT(room.hours.hours.size(), 100u);
  for (const std::size_t h : {std::size_t{7}, std::size_t{100}}) {
    for (PortalState& p : state.portals) p.environment = room.hours.hours[h].sky;
    relit->apply(state);
    twin->apply(state);
    const std::vector<Rgb> a = relit->sensor_irradiance(), b = twin->sensor_irradiance();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t s = 0; s < a.size(); ++s) EXPECT_EQ(a[s], b[s]) << "hour " << h;
    EXPECT_EQ(relit->sensor_sun_irradiance(), twin->sensor_sun_irradiance());
  }
}

TEST(AnnualStreams, TheValuesDoNotDependOnHowManyStreamsRelitTheHours) {
  const SpringRoom& room = spring_room();
  const std::unique_ptr<RelitScene> relit = open_for_annual(room.rlt);
  const LightingState base = daylight_alone(relit->state());
  const std::vector<std::size_t> sets = every_sensor_set(relit->scene());
  AnnualDaylight one, two;
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = annual_daylight(*relit, base, room.hours.hours, sets);
  }
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = annual_daylight(*relit, base, room.hours.hours, sets);
  }
  EXPECT_EQ(one.values.streams, 1u);
  EXPECT_EQ(two.values.streams, 2u);
  EXPECT_EQ(one.values.lux, two.values.lux);
  EXPECT_EQ(one.values.direct_sun_lux, two.values.direct_sun_lux);
  // Daylight and sun reached the sensors: the comparison is not of zeros.
  EXPECT_GT(*std::max_element(one.values.lux.begin(), one.values.lux.end()), 1000.0f);
  EXPECT_GT(*std::max_element(one.values.direct_sun_lux.begin(), one.values.direct_sun_lux.end()),
            1000.0f);
}

}  // namespace
}  // namespace relight
