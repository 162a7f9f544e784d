// EnergyPlus weather files (.epw; EnergyPlus "Auxiliary Programs", Weather Converter, "EnergyPlus
// Weather File (EPW) Data Dictionary"): the location and the hourly records `relight annual`
// lights a scene with.
//
// The file: eight header lines, the first
//   LOCATION,city,state,country,source,WMO,latitude,longitude,time zone,elevation
// (degrees north and east, hours from UTC of local standard time, metres), the eighth beginning
// DATA PERIODS; then one record per line, 35 comma-separated fields, of which relight reads
//   1 year, 2 month, 3 day, 4 hour (1..24: the hour ENDING then, local standard time),
//   8 dew point temperature (°C; 99.9 = missing),
//   15 direct normal radiation, 16 diffuse horizontal radiation (Wh/m² over the hour, read
//   as the hour's mean irradiance in W/m²; 9999 = missing),
//   33 albedo (the ground's reflectance, 0..1; 999 = missing).
// The other fields must be there (a record with fewer than 35 is truncated) but are not read.
//
// Choices: a missing radiation value is an error (a year with holes would give annual metrics
// that look complete and are not); a missing dew point is not (the Perez efficacies then take
// 2 cm of precipitable water), nor is a missing albedo (the ground then reflects 0.2, Perez's
// and Radiance's default). Radiation above 1500 W/m² (beyond the solar constant) and dew
// points outside −90..60 °C are refused; so are dates that are not in the calendar (29 February
// of a year that is not a leap year included) and hours outside 1..24. Problems are
// InputError "FILE:LINE: field N (name): reason". Records need not be in order or cover a year.
// Tests: tests/light/epw_weather_test.cpp (synthetic files written by the test).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relight {

struct WeatherLocation {
  std::string city;
  double latitude_deg = 0;     // north positive
  double longitude_deg = 0;    // east positive
  double time_zone_hours = 0;  // local standard time = UTC + time_zone_hours
  double elevation_m = 0;
};

struct WeatherRecord {
  int year = 0, month = 1, day = 1;
  int hour = 1;  // 1..24, the hour ending then
  std::optional<double> dew_point_c;
  double direct_normal_irradiance = 0;       // W/m²
  double diffuse_horizontal_irradiance = 0;  // W/m²
  std::optional<double> ground_albedo;       // 0..1, when the record gives one
  int line = 0;                              // in the file, for messages
};

struct WeatherFile {
  WeatherLocation location;
  std::vector<WeatherRecord> records;
};

// Parses the text of an EPW file; `name` is the file named in messages.
WeatherFile parse_epw(std::string_view text, const std::string& name);
// Reads and parses an EPW file.
WeatherFile read_epw(const std::filesystem::path& file);

}  // namespace relight
