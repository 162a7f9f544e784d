// The daylight available at a site by solar altitude; formulas and sources in
// daylight_availability.h.
#include "light/daylight_availability.h"

#include <algorithm>
#include <cmath>

#include "light/perez_sky.h"

namespace relight {

double kasten_young_air_mass(double zenith_rad) {
  const double z = std::clamp(zenith_rad, 0.0, kPi / 2);
  return 1.0 / (std::cos(z) + 0.50572 * std::pow(96.07995 - z * (180.0 / kPi), -1.6364));
}

SolarIrradiance clear_sky_irradiance(Vec3 sun_direction, int day_of_year, double elevation_m,
                                     double linke_turbidity) {
  const Vec3 s = normalize(sun_direction);
  if (!(s.y > 0)) return {};
  const double cos_z = s.y;
  const double am = kasten_young_air_mass(std::acos(cos_z));
  const double i0 = extraterrestrial_irradiance(day_of_year);
  const double h = elevation_m;
  const double tl = linke_turbidity;
  const double fh1 = std::exp(-h / 8000.0);
  const double fh2 = std::exp(-h / 1250.0);
  const double cg1 = 5.09e-5 * h + 0.868;
  const double cg2 = 3.92e-5 * h + 0.0387;
  SolarIrradiance r;
  r.global_horizontal = cg1 * i0 * cos_z * std::exp(-cg2 * am * (fh1 + fh2 * (tl - 1)));
  const double b = 0.664 + 0.163 / fh1;
  const double beam = b * i0 * std::exp(-0.09 * am * (tl - 1));
  const double beam_from_global =
      r.global_horizontal * (1 - (0.1 - 0.2 * std::exp(-tl)) / (0.1 + 0.882 / fh1)) / cos_z;
  r.direct_normal = std::max(0.0, std::min(beam, beam_from_global));
  r.diffuse_horizontal = std::max(0.0, r.global_horizontal - r.direct_normal * cos_z);
  return r;
}

double sky_type_cloud_cover_oktas(int sky_type) {
  if (sky_type >= 11) return 0;
  if (sky_type >= 6) return 4;
  return 8;
}

SolarIrradiance clouded_irradiance(const SolarIrradiance& cloudless, double oktas,
                                   Vec3 sun_direction) {
  if (!(oktas > 0)) return cloudless;
  const double cos_z = normalize(sun_direction).y;
  if (!(cos_z > 0)) return {};
  const double n = std::min(oktas, 8.0) / 8.0;
  SolarIrradiance r;
  r.global_horizontal = cloudless.global_horizontal * (1 - 0.75 * std::pow(n, 3.4));
  r.diffuse_horizontal = r.global_horizontal * (0.3 + 0.7 * n * n);
  r.direct_normal = (r.global_horizontal - r.diffuse_horizontal) / cos_z;
  return r;
}

DaylightAvailability cie_sky_daylight(int sky_type, Vec3 sun_direction, int day_of_year,
                                      double elevation_m, double linke_turbidity) {
  const SolarIrradiance irradiance = clouded_irradiance(
      clear_sky_irradiance(sun_direction, day_of_year, elevation_m, linke_turbidity),
      sky_type_cloud_cover_oktas(sky_type), sun_direction);
  if (!(irradiance.global_horizontal > 0)) return {};
  PerezWeather weather;
  weather.direct_normal_irradiance = irradiance.direct_normal;
  weather.diffuse_horizontal_irradiance = irradiance.diffuse_horizontal;
  weather.day_of_year = day_of_year;
  const PerezSkyCondition condition = perez_sky_condition(weather, sun_direction);
  return {irradiance.diffuse_horizontal * perez_diffuse_efficacy(condition),
          irradiance.direct_normal * perez_direct_efficacy(condition)};
}

}  // namespace relight
