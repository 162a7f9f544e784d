// The Perez all-weather sky from weather data: the sky's luminance distribution from the
// direct normal and diffuse horizontal irradiance, and the luminous efficacies that turn those
// irradiances into illuminances, as Radiance's gendaylit computes them.
//
//  * Sky condition parameters (Perez, Seals & Michalsky 1993, Solar Energy 50(3), §2; the same as
//    Perez, Ineichen, Seals, Michalsky & Stewart 1990, Solar Energy 44(5), Eq. 1–2):
//      clearness  ε = ((D + I)/D + κZ³) / (1 + κZ³),  κ = 1.041, Z the solar zenith in radians,
//      brightness Δ = D·m / I₀,
//    D the diffuse horizontal and I the direct normal irradiance (W/m²), m the relative optical
//    air mass (Kasten 1966: m = 1/(cos Z + 0.15·(93.885 − Z°)^−1.253)), I₀ the extraterrestrial
//    normal irradiance 1367 W/m² times the eccentricity correction of Spencer 1971
//    (1.00011 + 0.034221 cos Γ + 0.00128 sin Γ + 0.000719 cos 2Γ + 0.000077 sin 2Γ,
//    Γ = 2π(day − 1)/365). ε falls into eight bins, edges 1, 1.065, 1.23, 1.5, 1.95, 2.8, 4.5, 6.2.
//  * Luminance coefficients (Perez et al. 1993, Table 1 and Eq. 2–3): for each of a..e and each
//    bin, x = x1 + x2·Z + Δ·(x3 + x4·Z); in the first bin (overcast) c and d take the forms
//      c = exp((Δ·(c1 + c2·Z))^c3) − c4,  d = −exp(Δ·(d1 + d2·Z)) + d3 + Δ·d4.
//    Δ is held in 0.01..0.6 in these formulas, the range the model was fitted to (gendaylit
//    refuses records outside it; a low sun under a bright overcast reaches Δ ≈ 1, where the
//    first bin's c grows to ~10²); for 1.065 < ε < 2.8 it is held at 0.2 or more
//    (gendaylit's correction, which keeps intermediate skies with a very dark dome from turning
//    the gradation over). The efficacies below take Δ as it is.
//    The distribution itself is SkyFormula::kPerez of light/sky_model.h.
//  * Luminous efficacies (Perez et al. 1990, Table 4, Eq. 7–8), W the atmospheric precipitable
//    water in cm:
//      diffuse  K_d = a + b·W + c·cos Z + d·ln Δ              (lm/W)
//      direct   K_b = max(0, a + b·W + c·exp(5.73·Z − 5) + d·Δ)
//    W from the surface dew point T_d (°C): W = exp(0.07·T_d − 0.075) (Perez et al. 1990, after
//    Wright, Perez & Michalsky 1989); W = 2 cm when no dew point is given (gendaylit's default).
//  * The sky: the dome scaled so that its horizontal illuminance is D·K_d (the model's
//    normalisation), a 0.53° sun disc whose normal illuminance is I·K_b, a ground of the given
//    albedo (light/sky_model.h). With the sun below the horizon there is no disc, and the model's
//    zenith-dependent terms are taken at Z = 90°.
// Tests: tests/light/perez_sky_test.cpp (normalisation, the efficacies against Table 4 by hand,
// the overcast and clear limits against the CIE skies' shapes).
#pragma once

#include <optional>

#include "light/sky_model.h"
#include "math/vec3.h"

namespace relight {

inline constexpr double kSolarConstant = 1367.0;  // W/m², as Perez et al. 1990 and gendaylit
inline constexpr double kPerezMinBrightness = 0.01, kPerezMaxBrightness = 0.6;

// The weather a Perez sky is made from.
struct PerezWeather {
  double direct_normal_irradiance = 0;       // I, W/m² (>= 0)
  double diffuse_horizontal_irradiance = 0;  // D, W/m² (>= 0)
  std::optional<double> dew_point_c;         // T_d, °C; none: W = 2 cm
  int day_of_year = 0;                       // 1..366; 0: no date (eccentricity 1)
};

// The sky condition: ε, Δ, the solar zenith Z used in the formulas (radians, at most π/2), W,
// and the clearness bin (0..7). With D = 0 the sky is black: ε is taken as infinite (bin 7) and
// Δ as 0.
struct PerezSkyCondition {
  double clearness = 1;   // ε
  double brightness = 0;  // Δ
  double zenith = 0;      // Z, radians
  double precipitable_water_cm = 2;
  int bin = 0;
};

double relative_air_mass(double zenith_rad);          // Kasten 1966, Z <= 90°
double extraterrestrial_irradiance(int day_of_year);  // I₀, W/m² (1367 for day 0)
double precipitable_water_cm(double dew_point_c);
// The bin (0..7) of a clearness ε >= 1.
int perez_clearness_bin(double clearness);

PerezSkyCondition perez_sky_condition(const PerezWeather& weather, Vec3 sun_direction);

// a..e of Table 1 for the condition.
CieSkyParameters perez_luminance_coefficients(const PerezSkyCondition& condition);

// K_d and K_b (lm/W) of Table 4 for the condition. K_d of a black sky (Δ = 0) is 0.
double perez_diffuse_efficacy(const PerezSkyCondition& condition);
double perez_direct_efficacy(const PerezSkyCondition& condition);

// The whole sky of a weather record with the sun in `sun_direction` (unit or not, non-zero).
// Throws std::invalid_argument for negative or non-finite irradiances or albedo outside 0..1.
SkyModel make_perez_sky(const PerezWeather& weather, Vec3 sun_direction, double ground_albedo);

}  // namespace relight
