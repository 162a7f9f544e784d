// A synthetic EnergyPlus weather file for tests (no weather file is packaged): a year of
// hourly records at a given place whose direct and diffuse irradiance follow the sun through
// a repeating pattern of overcast, clear and intermediate days.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "light/sun_position.h"
#include "scene/environment_spec.h"

namespace relight::testing {

struct SyntheticPlace {
  const char* city = "Testville";
  double latitude_deg = 48.14, longitude_deg = 11.58, time_zone_hours = 1;
  int year = 2023;
  int first_month = 1, last_month = 12;  // the months written
};

// The irradiances of day d (of the year) with the sun at altitude h (degrees, > 0).
struct SyntheticSky {
  double direct, diffuse, dew_point;
};
inline SyntheticSky synthetic_sky(int d, double h) {
  const double s = std::sin(radians(h));
  const double dew = 4 + 8 * std::sin(2 * kPi * (d - 110) / 365.0);
  switch (d % 3) {
    case 0:  // overcast
      return {0, 30 + 260 * s, dew};
    case 1:  // clear
      return {std::min(950.0, 1000 * std::exp(-0.14 / std::max(s, 0.05))), 40 + 70 * s, dew};
    default:  // intermediate
      return {380 * std::sqrt(s), 60 + 180 * s, dew};
  }
}

inline std::string synthetic_epw(const SyntheticPlace& place = {}) {
  std::ostringstream out;
  out << "LOCATION," << place.city << ",ST,Nowhere,synthetic,000000," << place.latitude_deg << ","
      << place.longitude_deg << "," << place.time_zone_hours << ",520.0\n"
      << "DESIGN CONDITIONS,0\nTYPICAL/EXTREME PERIODS,0\nGROUND TEMPERATURES,0\n"
      << "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\nCOMMENTS 1,written by a test\nCOMMENTS 2,\n"
      << "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31\n";
  for (int month = place.first_month; month <= place.last_month; ++month) {
    for (int day = 1; day <= days_in_month(place.year, month); ++day) {
      const int d = day_of_year({place.year, month, day, 0, 0, 0});
      for (int hour = 1; hour <= 24; ++hour) {
        const UtcTime utc =
            utc_from_local(place.year, month, day, hour - 1, 30, 0, place.time_zone_hours);
        const double h =
            psa_sun_position(utc, place.latitude_deg, place.longitude_deg).altitude_deg();
        const SyntheticSky sky = h > 0 ? synthetic_sky(d, h) : SyntheticSky{0, 0, 3};
        out << place.year << "," << month << "," << day << "," << hour
            << ",60,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9,12.0," << sky.dew_point
            << ",70,95000,0,0,300,"
            << sky.direct * std::max(0.0, std::sin(radians(h))) + sky.diffuse << "," << sky.direct
            << "," << sky.diffuse
            << ",0,0,0,0,180,2.0,5,5,20.0,77777,9,999999999,1.5,0.1,0,88,0.2,0,0\n";
      }
    }
  }
  return out.str();
}

}  // namespace relight::testing
