// Climate-based daylight metrics (runtime/daylight_metrics.h) by hand on small series, and the
// hours `relight annual` evaluates (runtime/annual_daylight.h).
#include <gtest/gtest.h>

#include <vector>

#include "light/environment.h"
#include "runtime/annual_daylight.h"
#include "runtime/daylight_metrics.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

// Four hours × three sensors.
const std::vector<float> kLux = {
    50,  300,  2500,  //
    99,  299,  2000,  //
    100, 1000, 2001,  //
    400, 1500, 20000,
};
const std::vector<float> kSun = {
    0, 1000, 5000,  //
    0, 999,  0,     //
    0, 0,    1000,  //
    0, 0,    0,
};

TEST(DaylightMetrics, PerSensorSharesCountedByHand) {
  const std::vector<SensorDaylight> d = sensor_daylight(kLux, kSun, 3);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_DOUBLE_EQ(d[0].da300, 0.25);  // 400
  EXPECT_DOUBLE_EQ(d[1].da300, 0.75);  // 300, 1000, 1500 (299 falls short)
  EXPECT_DOUBLE_EQ(d[2].da300, 1.0);
  EXPECT_DOUBLE_EQ(d[0].udi_fell_short, 0.5);  // 50, 99
  EXPECT_DOUBLE_EQ(d[0].udi_useful, 0.5);      // 100, 400
  EXPECT_DOUBLE_EQ(d[2].udi_useful, 0.25);     // 2000 is useful
  EXPECT_DOUBLE_EQ(d[2].udi_exceeded, 0.75);   // 2500, 2001, 20000
  for (const SensorDaylight& s : d) {
    EXPECT_DOUBLE_EQ(s.udi_fell_short + s.udi_useful + s.udi_exceeded, 1.0);
  }
  EXPECT_EQ(d[0].ase_hours, 0);
  EXPECT_EQ(d[1].ase_hours, 1);  // 1000 counts, 999 does not
  EXPECT_EQ(d[2].ase_hours, 2);
}

TEST(DaylightMetrics, SetMetricsAndTheEn17037Level) {
  const std::vector<SensorDaylight> d = sensor_daylight(kLux, kSun, 3);
  const SetDaylight all = set_daylight(kLux, 3, d, 0, 3);
  EXPECT_DOUBLE_EQ(all.sda300, 2.0 / 3);  // DA 0.75 and 1.0 reach 50 %
  EXPECT_DOUBLE_EQ(all.ase, 0.0);         // nobody has more than 250 hours
  EXPECT_DOUBLE_EQ(all.mean_da300, (0.25 + 0.75 + 1.0) / 3);
  // Per hour: ≥ 50 % of points at E_T and ≥ 95 % (all three) at E_TM.
  //   high (750/500): hours 3 (100 < 500) no, 4 (400 < 500) no → 0 of 4.
  //   medium (500/300): hour 4 (400 ≥ 300, 1500 and 20000 ≥ 500) yes, the others no → 1 of 4.
  //   minimum (300/100): hours 3 (100,1000,2001) and 4 → 2 of 4: reached.
  EXPECT_EQ(all.en17037, DaylightProvision::kMinimum);
  // The last two sensors alone: high (750 over one of the two, 500 over both) in hours 3 and
  // 4, 2 of 4: reached.
  const SetDaylight two = set_daylight(kLux, 3, d, 1, 2);
  EXPECT_EQ(two.en17037, DaylightProvision::kHigh);
  EXPECT_STREQ(daylight_provision_name(two.en17037), "high");
  const SetDaylight dark = set_daylight(std::vector<float>(12, 50.0f), 3, d, 0, 3);
  EXPECT_EQ(dark.en17037, DaylightProvision::kNone);
}

TEST(AnnualDaylight, OccupiedHoursWithTheSunUpAtTheHalfHour) {
  EXPECT_FALSE(parse_occupied_period("18:00-08:00").has_value());
  EXPECT_FALSE(parse_occupied_period("8:00-18:00").has_value());
  EXPECT_FALSE(parse_occupied_period("08:00-24:30").has_value());
  const auto all_day = parse_occupied_period("00:00-24:00");
  ASSERT_TRUE(all_day.has_value());
  EXPECT_EQ(all_day->end_minutes, 1440);
  testing::SyntheticPlace place;
  place.first_month = place.last_month = 6;
  const WeatherFile june = parse_epw(testing::synthetic_epw(place), "june.epw");
  const AnnualHours office = annual_hours(june, {}, 0);
  // 08:00–18:00: the hours ending 9..18 (evaluated 08:30..17:30), ten a day, all with the sun
  // up in June at 48° N.
  EXPECT_EQ(office.occupied, 300u);
  EXPECT_EQ(office.hours.size(), 300u);
  EXPECT_EQ(office.hours.front().record.hour, 9);
  EXPECT_EQ(office.hours.front().sky.sun.local_time.hour, 8);
  EXPECT_EQ(office.hours.front().sky.sun.local_time.minute, 30);
  EXPECT_EQ(office.hours.back().record.hour, 18);
  const AnnualHours day = annual_hours(june, *all_day, 0);
  EXPECT_EQ(day.occupied, 720u);
  // Sunrise about 05:15, sunset about 21:15 local standard time (UTC+1) in Munich in June:
  // the hours evaluated at 05:30 .. 20:30 → 16 a day.
  EXPECT_EQ(day.hours.size(), 30u * 16);
  for (const AnnualHour& h : day.hours) {
    EXPECT_GT(sun_direction(h.sky.sun).y, 0);
    EXPECT_EQ(h.sky.type, EnvironmentType::kPerezSky);
    EXPECT_EQ(h.sky.direct_normal_irradiance, h.record.direct_normal_irradiance);
    EXPECT_EQ(h.sky.ground_albedo, 0.2);  // the synthetic file's field 33
  }
  // A record's own albedo lights the ground; without one it reflects 0.2.
  WeatherRecord snow = day.hours.front().record;
  snow.ground_albedo = 0.8;
  EXPECT_EQ(record_sky(june.location, snow, 0).ground_albedo, 0.8);
  snow.ground_albedo.reset();
  EXPECT_EQ(record_sky(june.location, snow, 0).ground_albedo, 0.2);
}

}  // namespace
}  // namespace relight
