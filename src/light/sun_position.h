// Sun position from date, time and place: the PSA algorithm of
//   M. Blanco-Muriel, D. C. Alarcón-Padilla, T. López-Moratalla, M. Lara-Coira, "Computing the
//   solar vector", Solar Energy 70(5), 431–441, 2001 (Eq. 1–16 of its §3: Julian day; ecliptic
//   longitude and obliquity from Ω, L, g; right ascension and declination; Greenwich and local
//   mean sidereal time; hour angle; zenith and azimuth; parallax correction
//   θz += (R_earth / AU)·sin θz).
// Its stated accuracy is 0.5 arc minute (0.0083°) over 1999–2015, far inside the 0.53° sun
// disc. The same equations with the coefficients refitted for 2020–2050 are in
//   M. J. Blanco, K. Milidonis, A. Bonanos, "Updating the PSA sun position algorithm",
//   Solar Energy 212, 339–341, 2020,
// which relight uses by default for dates from 2016 on (PsaCoefficients::kAuto).
// Refraction is not modelled (as in PSA): the positions are true (geometric) topocentric ones.
//
// Conventions: azimuth measured from NORTH, CLOCKWISE TOWARD EAST, in [0°, 360°); zenith from
// the local vertical. In the world frame (right-handed, y up) NORTH IS −z and EAST IS +x, so
// the direction toward a sun at azimuth A and altitude h is
//   (cos h · sin A, sin h, −cos h · cos A)
// (A = 0 → −z, A = 90° → +x, A = 180° → +z (south), A = 270° → −x).
#pragma once

#include "math/vec3.h"

namespace relight {

// A UTC instant: civil date plus decimal hours. `hours` may lie outside [0, 24) (e.g. after
// subtracting a UTC offset); the instant is then that many hours from the date's 0 h.
struct UtcTime {
  int year = 2000, month = 1, day = 1;
  double hours = 0;
};

// The UTC instant of a local civil time that is `utc_offset_hours` ahead of UTC.
UtcTime utc_from_local(int year, int month, int day, int hour, int minute, double second,
                       double utc_offset_hours);

enum class PsaCoefficients {
  k2001,  // Blanco-Muriel et al. 2001 (fitted to 1999–2015)
  k2020,  // Blanco, Milidonis & Bonanos 2020 (fitted to 2020–2050)
  kAuto,  // k2001 before 2016, k2020 from 2016 on
};

struct SunPosition {
  double zenith_deg = 0;   // from the vertical, parallax-corrected
  double azimuth_deg = 0;  // from north clockwise toward east, [0, 360)
  double altitude_deg() const { return 90.0 - zenith_deg; }
};

// PSA sun position for a UTC instant at latitude (deg, north positive) and longitude (deg,
// east positive).
SunPosition psa_sun_position(const UtcTime& utc, double latitude_deg, double longitude_deg,
                             PsaCoefficients coefficients = PsaCoefficients::kAuto);

// Elapsed days since 2000-01-01 12:00 UT (JD 2451545.0), as PSA's Eq. 1–2 compute it.
double psa_elapsed_julian_days(const UtcTime& utc);

// Unit world direction toward azimuth / altitude (degrees) in the convention above.
Vec3 horizontal_to_world(double azimuth_deg, double altitude_deg);
// Its inverse for a non-zero direction: azimuth in [0, 360), altitude in [−90, 90].
struct HorizontalAngles {
  double azimuth_deg = 0, altitude_deg = 0;
};
HorizontalAngles world_to_horizontal(Vec3 dir);

}  // namespace relight
