// Climate-based daylight metrics from a year of hourly sensor illuminance (`relight annual`,
// runtime/annual_daylight.h), as lighting designers and rating systems use them. Every share
// is of the hours evaluated — the occupied hours with the sun up — and of the sensor points
// of a set, each point standing for an equal area (a regular grid):
//  * DA300 (daylight autonomy; Reinhart & Walkenhorst 2001): the share of hours with
//    E >= 300 lx.
//  * UDI (useful daylight illuminance; Nabil & Mardaljevic 2005, their bands):
//    fell short E < 100 lx, useful 100 <= E <= 2000 lx, exceeded E > 2000 lx; the three
//    shares add up to 1.
//  * ASE hours: hours whose direct sunlight alone (no interreflection) is >= 1000 lx
//    (IES LM-83-12).
//  * Per set: sDA300/50% — the share of points with DA300 >= 0.5; ASE1000,250 — the share of
//    points with more than 250 ASE hours (IES LM-83-12); the mean DA300.
//  * EN 17037:2018 daylight provision (vertical openings), spatial then temporal: an hour meets
//    a level when at least 50 % of the points get its target E_T and at least 95 % its
//    minimum target E_TM; the level is reached when at least half of the hours meet it.
//    Levels: minimum 300 / 100 lx, medium 500 / 300 lx, high 750 / 500 lx.
// Tests: tests/runtime/daylight_metrics_test.cpp (by hand on small series).
#pragma once

#include <span>
#include <string>
#include <vector>

namespace relight {

struct SensorDaylight {
  double da300 = 0;
  double udi_fell_short = 0, udi_useful = 0, udi_exceeded = 0;
  int ase_hours = 0;
};

// Per sensor (column) of the hours × sensors series `lux` and `direct_sun_lux`.
std::vector<SensorDaylight> sensor_daylight(std::span<const float> lux,
                                            std::span<const float> direct_sun_lux,
                                            std::size_t sensors);

enum class DaylightProvision { kNone, kMinimum, kMedium, kHigh };
const char* daylight_provision_name(DaylightProvision level);

struct SetDaylight {
  double sda300 = 0;  // share of points with DA300 >= 0.5
  double ase = 0;     // share of points with more than 250 ASE hours
  double mean_da300 = 0;
  DaylightProvision en17037 = DaylightProvision::kNone;
};

// One set: its points are the columns [first, first + count) of the series.
SetDaylight set_daylight(std::span<const float> lux, std::size_t sensors,
                         std::span<const SensorDaylight> per_sensor, std::size_t first,
                         std::size_t count);
// Every set of consecutive columns, `counts[k]` points for set k.
std::vector<SetDaylight> sets_daylight(std::span<const float> lux, std::size_t sensors,
                                       std::span<const SensorDaylight> per_sensor,
                                       std::span<const std::size_t> counts);

}  // namespace relight
