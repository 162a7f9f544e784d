// The Perez all-weather sky from weather data; formulas and sources in perez_sky.h.
#include "light/perez_sky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace relight {

namespace {

constexpr double kKappa = 1.041;  // Perez et al. 1990, Eq. 1 (Z in radians)

// Upper edges of the clearness bins 0..6 (bin 7 is open above).
constexpr std::array<double, 7> kBinEdges = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// Perez, Seals & Michalsky 1993, Table 1: per bin, a1..a4, b1..b4, c1..c4, d1..d4, e1..e4.
constexpr double kLuminance[8][5][4] = {
    {{1.3525, -0.2576, -0.2690, -1.4366},
     {-0.7670, 0.0007, 1.2734, -0.1233},
     {2.8000, 0.6004, 1.2375, 1.0000},
     {1.8734, 0.6297, 0.9738, 0.2809},
     {0.0356, -0.1246, -0.5718, 0.9938}},
    {{-1.2219, -0.7730, 1.4148, 1.1016},
     {-0.2054, 0.0367, -3.9128, 0.9156},
     {6.9750, 0.1774, 6.4477, -0.1239},
     {-1.5798, -0.5081, -1.7812, 0.1080},
     {0.2624, 0.0672, -0.2190, -0.4285}},
    {{-1.1000, -0.2515, 0.8952, 0.0156},
     {0.2782, -0.1812, -4.5000, 1.1766},
     {24.7219, -13.0812, -37.7000, 34.8438},
     {-5.0000, 1.5218, 3.9229, -2.6204},
     {-0.0156, 0.1597, 0.4199, -0.5562}},
    {{-0.5484, -0.6654, -0.2672, 0.7117},
     {0.7234, -0.6219, -5.6812, 2.6297},
     {33.3389, -18.3000, -62.2500, 52.0781},
     {-3.5000, 0.0016, 1.1477, 0.1062},
     {0.4659, -0.3296, -0.0876, -0.0329}},
    {{-0.6000, -0.3566, -2.5000, 2.3250},
     {0.2937, 0.0496, -5.6812, 1.8415},
     {21.0000, -4.7656, -21.5906, 7.2492},
     {-3.5000, -0.1554, 1.4062, 0.3988},
     {0.0032, 0.0766, -0.0656, -0.1294}},
    {{-1.0156, -0.3670, 1.0078, 1.4051},
     {0.2875, -0.5328, -3.8500, 3.3750},
     {14.0000, -0.9999, -7.1406, 7.5469},
     {-3.4000, -0.1078, -1.0750, 1.5702},
     {-0.0672, 0.4016, 0.3017, -0.4844}},
    {{-1.0000, 0.0211, 0.5025, -0.5119},
     {-0.3000, 0.1922, 0.7023, -1.6317},
     {19.0000, -5.0000, 1.2438, -1.9094},
     {-4.0000, 0.0250, 0.3844, 0.2656},
     {1.0468, -0.3788, -2.4517, 1.4656}},
    {{-1.0500, 0.0289, 0.4260, 0.3590},
     {-0.3250, 0.1156, 0.7781, 0.0025},
     {31.0625, -14.5000, -46.1148, 55.3750},
     {-7.2312, 0.4050, 13.3500, 0.6234},
     {1.5000, -0.6426, 1.8564, 0.5636}},
};

// Perez et al. 1990, Table 4: per bin, a, b, c, d.
constexpr double kDiffuseEfficacy[8][4] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},    {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98},
};
constexpr double kDirectEfficacy[8][4] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29},
};

bool finite_non_negative(double v) {
  return std::isfinite(v) && v >= 0;
}

}  // namespace

double relative_air_mass(double zenith_rad) {
  const double z = std::clamp(zenith_rad, 0.0, kPi / 2);
  return 1.0 / (std::cos(z) + 0.15 * std::pow(93.885 - degrees(z), -1.253));
}

double extraterrestrial_irradiance(int day_of_year) {
  if (day_of_year <= 0) return kSolarConstant;
  const double g = 2.0 * kPi * (day_of_year - 1) / 365.0;
  return kSolarConstant * (1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) +
                           0.000719 * std::cos(2 * g) + 0.000077 * std::sin(2 * g));
}

double precipitable_water_cm(double dew_point_c) {
  return std::exp(0.07 * dew_point_c - 0.075);
}

int perez_clearness_bin(double clearness) {
  int bin = 0;
  while (bin < static_cast<int>(kBinEdges.size()) && clearness >= kBinEdges[bin]) ++bin;
  return bin;
}

PerezSkyCondition perez_sky_condition(const PerezWeather& weather, Vec3 sun_direction) {
  PerezSkyCondition c;
  const Vec3 s = normalize(sun_direction);
  c.zenith = std::acos(std::clamp(s.y, 0.0, 1.0));
  c.precipitable_water_cm = weather.dew_point_c ? precipitable_water_cm(*weather.dew_point_c) : 2.0;
  const double d = weather.diffuse_horizontal_irradiance;
  if (d > 0) {
    const double kz3 = kKappa * c.zenith * c.zenith * c.zenith;
    c.clearness = ((d + weather.direct_normal_irradiance) / d + kz3) / (1.0 + kz3);
    c.brightness =
        d * relative_air_mass(c.zenith) / extraterrestrial_irradiance(weather.day_of_year);
  } else {
    c.clearness = std::numeric_limits<double>::infinity();
    c.brightness = 0;
  }
  c.bin = perez_clearness_bin(c.clearness);
  return c;
}

CieSkyParameters perez_luminance_coefficients(const PerezSkyCondition& condition) {
  const double z = condition.zenith;
  double delta = std::clamp(condition.brightness, kPerezMinBrightness, kPerezMaxBrightness);
  if (condition.clearness > 1.065 && condition.clearness < 2.8) delta = std::max(delta, 0.2);
  const auto& x = kLuminance[condition.bin];
  const auto linear = [&](int i) {
    return x[i][0] + x[i][1] * z + delta * (x[i][2] + x[i][3] * z);
  };
  CieSkyParameters p;
  p.a = linear(0);
  p.b = linear(1);
  p.e = linear(4);
  if (condition.bin == 0) {
    p.c = std::exp(std::pow(delta * (x[2][0] + x[2][1] * z), x[2][2])) - x[2][3];
    p.d = -std::exp(delta * (x[3][0] + x[3][1] * z)) + x[3][2] + delta * x[3][3];
  } else {
    p.c = linear(2);
    p.d = linear(3);
  }
  return p;
}

double perez_diffuse_efficacy(const PerezSkyCondition& condition) {
  if (!(condition.brightness > 0)) return 0;
  const auto& k = kDiffuseEfficacy[condition.bin];
  return k[0] + k[1] * condition.precipitable_water_cm + k[2] * std::cos(condition.zenith) +
         k[3] * std::log(condition.brightness);
}

double perez_direct_efficacy(const PerezSkyCondition& condition) {
  const auto& k = kDirectEfficacy[condition.bin];
  return std::max(0.0, k[0] + k[1] * condition.precipitable_water_cm +
                           k[2] * std::exp(5.73 * condition.zenith - 5.0) +
                           k[3] * condition.brightness);
}

SkyModel make_perez_sky(const PerezWeather& weather, Vec3 sun_direction, double ground_albedo) {
  if (!finite_non_negative(weather.direct_normal_irradiance) ||
      !finite_non_negative(weather.diffuse_horizontal_irradiance)) {
    throw std::invalid_argument("Perez sky: irradiances must be finite and >= 0");
  }
  if (weather.dew_point_c && !std::isfinite(*weather.dew_point_c)) {
    throw std::invalid_argument("Perez sky: the dew point must be finite");
  }
  const PerezSkyCondition condition = perez_sky_condition(weather, sun_direction);
  const double diffuse = weather.diffuse_horizontal_irradiance * perez_diffuse_efficacy(condition);
  const double direct = weather.direct_normal_irradiance * perez_direct_efficacy(condition);
  return make_perez_sky_from_horizontal_illuminance(perez_luminance_coefficients(condition),
                                                    sun_direction, diffuse, ground_albedo, direct);
}

}  // namespace relight
