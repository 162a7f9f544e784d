// The PSA sun position algorithm (Blanco-Muriel et al., Solar Energy 70(5), 2001, §3; the
// 2020 coefficients from Blanco, Milidonis & Bonanos, Solar Energy 212, 2020). See
// sun_position.h for the conventions.
#include "light/sun_position.h"

#include <algorithm>
#include <cmath>

namespace relight {

namespace {

// The 15 fitted coefficients, in the order of the equations that use them:
//   Ω = p0 + p1 n;  L = p2 + p3 n;  g = p4 + p5 n                       (ecliptic, rad)
//   λ = L + p6 sin g + p7 sin 2g + p8 + p9 sin Ω                        (ecliptic longitude)
//   ε = p10 + p11 n + p12 cos Ω                                         (obliquity)
//   GMST = p13 + p14 n + hours                                          (hours)
struct PsaTable {
  double p[15];
};

constexpr PsaTable kPsa2001 = {{2.1429, -0.0010394594, 4.8950630, 0.017202791698, 6.2400600,
                                0.0172019699, 0.03341607, 0.00034894, -0.0001134, -0.0000203,
                                0.4090928, -6.2140e-9, 0.0000396, 6.6974243242, 0.0657098283}};

constexpr PsaTable kPsa2020 = {{2.267127827, -9.300339267e-4, 4.895036035, 1.720279602e-2,
                                6.239468336, 1.720200135e-2, 3.338320972e-2, 3.497596876e-4,
                                -1.544353226e-4, -8.689729360e-6, 4.090904909e-1, -6.213605399e-9,
                                4.418094944e-5, 6.697096103, 6.570984737e-2}};

// Mean Earth radius and astronomical unit (km), PSA Eq. 15.
constexpr double kEarthMeanRadiusKm = 6371.01;
constexpr double kAstronomicalUnitKm = 149597890.0;

double wrap_two_pi(double a) {
  a = std::fmod(a, 2.0 * kPi);
  return a < 0 ? a + 2.0 * kPi : a;
}

}  // namespace

UtcTime utc_from_local(int year, int month, int day, int hour, int minute, double second,
                       double utc_offset_hours) {
  return {year, month, day, hour + minute / 60.0 + second / 3600.0 - utc_offset_hours};
}

double psa_elapsed_julian_days(const UtcTime& utc) {
  // Julian day number of the civil date at noon (the integer formula of PSA Eq. 1, which is
  // Fliegel & Van Flandern's; C++ integer division truncates toward zero, as it requires).
  const long a = (utc.month - 14) / 12;
  const long jdn = (1461L * (utc.year + 4800 + a)) / 4 + (367L * (utc.month - 2 - 12 * a)) / 12 -
                   (3L * ((utc.year + 4900 + a) / 100)) / 4 + utc.day - 32075;
  // Eq. 2: JD = JDN − ½ + hours/24; n = JD − 2451545.0. Subtract first to keep precision.
  return static_cast<double>(jdn - 2451545L) - 0.5 + utc.hours / 24.0;
}

SunPosition psa_sun_position(const UtcTime& utc, double latitude_deg, double longitude_deg,
                             PsaCoefficients coefficients) {
  if (coefficients == PsaCoefficients::kAuto) {
    coefficients = utc.year >= 2016 ? PsaCoefficients::k2020 : PsaCoefficients::k2001;
  }
  const double* p = (coefficients == PsaCoefficients::k2020 ? kPsa2020 : kPsa2001).p;
  const double n = psa_elapsed_julian_days(utc);

  // Ecliptic coordinates (Eq. 3–7).
  const double omega = p[0] + p[1] * n;
  const double mean_longitude = p[2] + p[3] * n;
  const double mean_anomaly = p[4] + p[5] * n;
  const double ecliptic_longitude = mean_longitude + p[6] * std::sin(mean_anomaly) +
                                    p[7] * std::sin(2.0 * mean_anomaly) + p[8] +
                                    p[9] * std::sin(omega);
  const double obliquity = p[10] + p[11] * n + p[12] * std::cos(omega);

  // Celestial coordinates (Eq. 8–9).
  const double sin_lambda = std::sin(ecliptic_longitude);
  const double right_ascension =
      wrap_two_pi(std::atan2(std::cos(obliquity) * sin_lambda, std::cos(ecliptic_longitude)));
  const double declination = std::asin(std::sin(obliquity) * sin_lambda);

  // Local coordinates (Eq. 10–14). The decimal hours entering GMST are the UTC hours of the
  // day; using hours outside [0, 24) with the matching date shifts GMST by whole days of 24 h,
  // i.e. by whole turns of the hour angle, which leaves the result unchanged.
  const double gmst_hours = p[13] + p[14] * n + utc.hours;
  const double lmst = radians(gmst_hours * 15.0 + longitude_deg);
  const double hour_angle = lmst - right_ascension;
  const double lat = radians(latitude_deg);
  const double cos_lat = std::cos(lat), sin_lat = std::sin(lat);
  const double cos_ha = std::cos(hour_angle);
  double zenith = std::acos(std::clamp(
      cos_lat * cos_ha * std::cos(declination) + std::sin(declination) * sin_lat, -1.0, 1.0));
  const double azimuth = wrap_two_pi(
      std::atan2(-std::sin(hour_angle), std::tan(declination) * cos_lat - sin_lat * cos_ha));

  // Parallax (Eq. 15–16): the topocentric zenith is larger by (R/AU)·sin θz.
  zenith += kEarthMeanRadiusKm / kAstronomicalUnitKm * std::sin(zenith);

  SunPosition out;
  out.zenith_deg = degrees(zenith);
  out.azimuth_deg = degrees(azimuth);
  if (out.azimuth_deg >= 360.0) out.azimuth_deg -= 360.0;
  return out;
}

Vec3 horizontal_to_world(double azimuth_deg, double altitude_deg) {
  const double a = radians(azimuth_deg), h = radians(altitude_deg);
  const double c = std::cos(h);
  return {c * std::sin(a), std::sin(h), -c * std::cos(a)};
}

HorizontalAngles world_to_horizontal(Vec3 dir) {
  const Vec3 d = normalize(dir);
  HorizontalAngles out;
  out.altitude_deg = degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
  double az = degrees(std::atan2(d.x, -d.z));
  if (az < 0) az += 360.0;
  if (az >= 360.0) az -= 360.0;
  out.azimuth_deg = az;
  return out;
}

}  // namespace relight
