// How bright a CIE standard sky and its sun are at a given solar altitude, when a scene gives the
// sun's place and time but no brightness: the daylight available at the site.
//
//  * Cloudless atmosphere: the clear-sky model of P. Ineichen and R. Perez, "A new airmass
//    independent formulation for the Linke turbidity coefficient", Solar Energy 73(3), 151–157,
//    2002 (Eq. 7–10, without the optional low-sun enhancement exp(0.01·AM^1.8)):
//      G   = c_g1 · I₀ · cos Z · exp(−c_g2 · AM · (f_h1 + f_h2 · (T_L − 1)))
//      B_n = min( b · I₀ · exp(−0.09 · AM · (T_L − 1)),
//                 G · (1 − (0.1 − 0.2·exp(−T_L)) / (0.1 + 0.882/f_h1)) / cos Z ),
//      D   = G − B_n · cos Z,
//    c_g1 = 5.09·10⁻⁵·h + 0.868, c_g2 = 3.92·10⁻⁵·h + 0.0387, f_h1 = exp(−h/8000),
//    f_h2 = exp(−h/1250), b = 0.664 + 0.163/f_h1, h the site's elevation (m), T_L the Linke
//    turbidity at air mass 2, AM the relative optical air mass of F. Kasten and A. T. Young,
//    "Revised optical air mass tables and approximation formula", Applied Optics 28(22),
//    4735–4738, 1989: AM = 1/(cos Z + 0.50572·(96.07995° − Z)^−1.6364), and I₀ the
//    extraterrestrial normal irradiance of the date (light/perez_sky.h, Spencer 1971).
//  * Clouds, by the ISO 15469 sky groups: clear skies (types 11–15) are the cloudless
//    atmosphere; intermediate skies (6–10) carry half the sky covered (4 oktas) and overcast
//    skies (1–5 and the traditional overcast sky) all of it (8 oktas), by the cloud-cover
//    relations of F. Kasten and G. Czeplak, "Solar and terrestrial radiation dependent on the
//    amount and type of cloud", Solar Energy 24, 177–189, 1980:
//      G(N) = G(0) · (1 − 0.75 · (N/8)^3.4),   D(N) = G(N) · (0.3 + 0.7 · (N/8)²),
//    the beam the rest, B_n = (G − D)/cos Z: an overcast sky has no sun, G(8) = G(0)/4, all
//    diffuse.
//  * Irradiance to illuminance: the luminous efficacies of Perez et al. 1990 (light/perez_sky.h)
//    for the sky condition (ε, Δ) these irradiances make, W = 2 cm of precipitable water:
//      E_sky = D · K_d   (the dome's diffuse horizontal illuminance, lx),
//      E_sun = B_n · K_b (the sun disc's normal illuminance, lx).
//  * No twilight: with the sun's centre at or below the horizon both are 0.
// Tests: tests/light/daylight_availability_test.cpp (the formulas evaluated by hand at several
// altitudes for types 1, 7, 12 and overcast; elevation and turbidity; night).
#pragma once

#include "math/vec3.h"

namespace relight {

struct SolarIrradiance {
  double global_horizontal = 0;   // G, W/m²
  double direct_normal = 0;       // B_n, W/m²
  double diffuse_horizontal = 0;  // D, W/m²
};

// Kasten & Young 1989, zenith in radians (held at 90° and below).
double kasten_young_air_mass(double zenith_rad);

// The cloudless atmosphere of Ineichen & Perez 2002 with the sun in `sun_direction` (any length,
// non-zero). day_of_year 0 takes the mean extraterrestrial irradiance. All 0 with the sun at or
// below the horizon.
SolarIrradiance clear_sky_irradiance(Vec3 sun_direction, int day_of_year, double elevation_m,
                                     double linke_turbidity);

// The cloud cover (oktas, 0..8) the model gives CIE sky type 0 (traditional overcast) or 1..15.
double sky_type_cloud_cover_oktas(int sky_type);

// Kasten & Czeplak 1980 applied to a cloudless atmosphere: the global and diffuse irradiance
// under N oktas of cloud (N = 0 returns the cloudless split unchanged).
SolarIrradiance clouded_irradiance(const SolarIrradiance& cloudless, double oktas,
                                   Vec3 sun_direction);

struct DaylightAvailability {
  double sky_horizontal_illuminance = 0;  // lx, the dome alone
  double sun_normal_illuminance = 0;      // lx on a plane facing the sun
};

// The sky and sun of CIE sky type `sky_type` (0 or 1..15) at the sun's position.
DaylightAvailability cie_sky_daylight(int sky_type, Vec3 sun_direction, int day_of_year,
                                      double elevation_m, double linke_turbidity);

}  // namespace relight
