// Sky luminance models and the sun disc, in absolute photometric units (cd/m², lx).
//
//  * CIE standard general sky, ISO 15469:2004 / CIE S 011/E:2003 (Kittler, Darula, Perez):
//      L(Z, χ)/Lz = f(χ)·φ(Z) / (f(Zs)·φ(0))
//      gradation   φ(Z) = 1 + a·exp(b / cos Z)   for 0 <= Z < 90°,  φ(90°) = 1
//      indicatrix  f(χ) = 1 + c·(exp(d·χ) − exp(d·π/2)) + e·cos²χ
//    Z: zenith angle of the sky element, Zs: of the sun, χ: angular distance element–sun.
//    Fifteen parameter sets (a, b, c, d, e), types 1..15 (table in shared/notes/photometry.md):
//    1–5 overcast-like (1 ≈ the traditional overcast sky: E_h/Lz 0.25 % higher, L/Lz within
//    0.092, most different 10°–20° above the horizon; 5 uniform), 6–10 intermediate,
//    11–15 clear (12 = the CIE standard clear sky).
//  * Traditional CIE overcast sky (Moon & Spencer 1942, adopted by the CIE in 1955):
//      L = Lz·(1 + 2 sin h)/3 = Lz·(1 + 2 cos Z)/3,  whose horizontal illuminance is
//      E_h = ∫ L cos Z dω = (7π/9)·Lz.
//    Represented as sky type 0 (kTraditionalOvercastSky).
//  * Absolute scale: by the zenith luminance Lz, or by the sky's diffuse horizontal
//    illuminance E_h = ∫_{upper hemisphere} L cos Z dω, computed by a product quadrature
//    (sky_dome_quadrature below) of the tabulated dome (SkyTable below; converged to ~1e-7
//    relative for every type and sun position, see sky_model_test.cpp).
//  * Ground (below the horizon): a uniform Lambertian luminance
//      L_g = ground_albedo · (E_h,sky + E_h,sun) / π,  E_h,sun = E_sun,n · sin h_s (h_s > 0).
//  * Sun: a disc of angular diameter 0.53° and uniform luminance L_s chosen so that the
//    illuminance on a plane normal to the sun is the given E_sun,n:
//      E_sun,n = ∫_disc L_s cos α dω = L_s · π sin²r   (r = 0.265°, exactly),
//    so L_s = E_sun,n / (π sin² r) ≈ 1.49·10⁹ cd/m² for 100 klx. The disc's ∫ L dω is
//    L_s·2π(1 − cos r) = E_sun,n · 2/(1 + cos r). A sun whose centre is below the horizon has
//    no disc (and adds nothing to the ground).
// World frame: right-handed, y up, north −z, east +x (light/sun_position.h). Directions are
// unit vectors pointing away from the observer (toward the sky element).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

struct CieSkyParameters {
  double a = 0, b = 0, c = 0, d = 0, e = 0;
};

// The ISO 15469 parameters of standard sky type 1..15. Throws std::invalid_argument for
// other types.
CieSkyParameters cie_sky_parameters(int type);

// φ(Z) from cos Z (1 at and below the horizon, cos Z <= 0).
double cie_gradation(const CieSkyParameters& p, double cos_zenith);
// f(χ), χ in radians.
double cie_indicatrix(const CieSkyParameters& p, double chi);

// L/Lz of sky type 0 (traditional overcast) or 1..15 in the unit direction `dir` with the sun
// in the unit direction `sun_dir` (which may be below the horizon). The formula continued
// below the horizon (cos Z < 0 treated as 0) is returned for dir.y < 0; the ground is
// SkyModel's business. Equals 1 at the zenith for every type.
double sky_relative_luminance(int sky_type, Vec3 dir, Vec3 sun_dir);

// A product quadrature over the upper hemisphere (y >= 0) suited to sky luminances: weights are
// solid angles (Σ = 2π) and Σ w·g(dir) ≈ ∫ g dω. Gauss–Legendre in the zenith angle Z (weight
// sin Z), split at the sun's Z when the sun is above the horizon (n_zenith nodes shared by the
// two panels in proportion to their lengths, at least 4 each), times Gauss–Legendre in azimuth
// on each half turn from the sun's meridian (n_azimuth/2 nodes each, rounded up). The only
// non-smooth point of a CIE sky, the cusp of exp(dχ) at the sun, thus lies on panel corners
// with the nodes clustering toward it (and in Z, unlike cos Z, χ stays smooth through the
// zenith); the horizon is an end of the Z interval, and exp(b/cos Z), all of whose derivatives
// vanish there, needs no special care.
struct DomeQuadrature {
  std::vector<Vec3> directions;
  std::vector<double> weights;
};
DomeQuadrature sky_dome_quadrature(Vec3 sun_dir, int n_zenith, int n_azimuth);
// The same rule unexpanded, a product of its zenith nodes (weights with sin Z) and its azimuth
// nodes (both half turns, the sun's side first; direction {sin Z·sin φ, cos Z, −sin Z·cos φ}):
// for the loops that use the rule's structure (a gradation per ring, a half turn by symmetry).
struct DomeRule {
  std::vector<double> zenith_sin, zenith_cos, zenith_weight;
  std::vector<double> azimuth_sin, azimuth_cos, azimuth_weight;
};
DomeRule sky_dome_rule(Vec3 sun_dir, int n_zenith, int n_azimuth);

// ∫_{upper hemisphere} (L/Lz) cos Z dω: the horizontal illuminance of a sky whose zenith
// luminance is 1 (7π/9 for the traditional overcast sky, π for type 5), by
// sky_dome_quadrature(sun_dir, n_zenith, n_azimuth) of the tabulated dome (SkyTable).
double sky_relative_horizontal_illuminance(int sky_type, Vec3 sun_dir, int n_zenith = 192,
                                           int n_azimuth = 384);

// ---- The sun disc -----------------------------------------------------------------------

inline constexpr double kSunAngularDiameterDeg = 0.53;

struct SunDisc {
  Vec3 direction{0, 1, 0};        // unit, toward the disc centre
  double angular_radius = 0;      // radians (half of 0.53°)
  double cos_angular_radius = 1;  // cos r
  double tan_angular_radius = 0;  // tan r: the cone's spread per metre along its axis
  double solid_angle = 0;         // 2π(1 − cos r), sr
  double normal_illuminance = 0;  // lx on a plane facing the sun: ∫_disc L cos α dω
  double luminance = 0;           // uniform over the disc, cd/m²
  // ∫_disc L dω = luminance · solid_angle (lx·sr/sr): what a cubemap texel or an SH
  // projection of the disc receives.
  double integrated_luminance() const { return luminance * solid_angle; }
};

// A 0.53° disc centred on the unit `direction` with the given normal illuminance (lx >= 0).
SunDisc make_sun_disc(Vec3 direction, double normal_illuminance);
// A uniform disc of any angular radius (radians, in (0, π/2)): a compact source of a map
// (light/compact_sources.h).
SunDisc make_source_disc(Vec3 direction, double angular_radius, double normal_illuminance);
// Its luminance in the unit direction dir: disc.luminance inside the disc, 0 outside.
double sun_disc_luminance(const SunDisc& disc, Vec3 dir);
// The direction of the disc at tangent-plane offset (x, y) · tan r from its centre, |(x, y)| ≤ 1
// on the disc.
Vec3 sun_disc_direction(const SunDisc& disc, double x, double y);
// `count` directions spread evenly over the disc's area (a Vogel spiral): point i at radius
// √((i + ½)/count) and angle i times the golden angle. The exact sun traces them for a
// penumbra (sources/portals/portal_sun.h); the visibility cuts spread the disc's light over
// them (light/environment_clusters.h).
std::vector<Vec3> sun_disc_spiral(const SunDisc& disc, int count);

// ---- A complete sky: dome, ground, optional sun ----------------------------------------

// The relative luminance formula of a sky dome. kCie: the ISO 15469 general sky of `sky_type`
// (above). kPerez: the Perez all-weather sky (light/perez_sky.h), the same product of a
// gradation and an indicatrix with coefficients (a..e) that vary continuously with the weather,
//   l(Z, γ) = max(0, (1 + a·exp(b / max(cos Z, 0.1)))·(1 + c·exp(d·γ) + e·cos²γ)),
// normalised to 1 at the zenith. Unlike the CIE indicatrix there is no −exp(dπ/2) term. Where
// the fitted coefficients leave the formula's domain it is guarded, as Radiance's gendaymtx
// does: b may come out positive (high suns with a dark, partly clear sky), and then the
// gradation grows without bound toward the horizon — it is held at its value 5.7° above the
// horizon (cos Z ≥ 0.1; gendaymtx samples no sky below 6°); negative luminances (a gradation
// that changes sign) are 0; a zenith of luminance (nearly) 0 is not normalised to 1 (the
// dome is then scaled by its horizontal illuminance alone).
enum class SkyFormula { kCie, kPerez };
inline constexpr double kPerezMinCosZenith = 0.1;
inline constexpr double kPerezMinZenith = 1e-6;

// ---- The dome tabulated ------------------------------------------------------------------

// The dome's relative luminance for the tens of thousands of directions of a cubemap or a
// quadrature (a sky's shell and its scaling, which `relight annual` makes for every hour of a
// year): its two factors, the gradation and the indicatrix, tabulated once per sky at
// kSkyTableIntervals + 1 nodes each and interpolated linearly — a square root and two table
// lookups a direction instead of two exponentials and an arc cosine. The gradation is tabulated
// over cos Z (a CIE sky), or over 1/max(cos Z, 0.1) (a Perez sky, whose guarded gradation
// 1 + a·exp(b·s) is then a plain exponential), the indicatrix over the chord |dir − sun| for
// χ <= 90° and over |dir + sun| beyond: unlike χ or cos χ, the chord makes the indicatrix smooth
// at both ends (the circumsolar peak, the antisolar point), so linear interpolation errs by
// ~h²·|f''|/8 there too. The traditional overcast sky, a linear gradation, is reproduced to
// rounding; every other sky differs from the formula by at most 2e-5 of the luminance plus the
// zenith's (1.3e-5 measured over every CIE type and a range of Perez skies, suns 2°–85°:
// tests/light/sky_model_test.cpp, SkyTable.*): far below the error of a cubemap texel's mean
// (~1e-3). Made with the sky (SkyModel::table); point evaluations (a ray of the reference, an
// eye's view) use the formula itself, sky_diffuse_luminance.
inline constexpr int kSkyTableIntervals = 1024;

struct SkyTable {
  double scale = 1;  // the normaliser 1/(f(Zs)·φ(0)): relative luminance 1 at the zenith
  Vec3 sun_direction{0, 1, 0};
  bool perez = false;  // gradation over 1/max(cos Z, 0.1), negative products clamped to 0
  std::vector<double> gradation, toward_sun, away_from_sun;
};

struct SkyModel {
  SkyFormula formula = SkyFormula::kCie;
  int sky_type = 0;                       // kCie: 0 = traditional overcast, 1..15
  Vec3 sun_direction{0, 1, 0};            // sun position used by the luminance distribution
  CieSkyParameters parameters;            // of sky_type (all 0 for type 0), or Perez's a..e
  double indicatrix_normaliser = 1;       // 1 / (f(Zs)·φ(0)) (1 for type 0)
  double zenith_luminance = 0;            // Lz, cd/m²
  double sky_horizontal_illuminance = 0;  // E_h of the dome alone, lx
  double sun_horizontal_illuminance = 0;  // E_sun,n · sin h_s (0 without a disc), lx
  double ground_albedo = 0.2;
  double ground_luminance = 0;  // cd/m², uniform below the horizon
  std::optional<SunDisc> sun;   // present when E_sun,n > 0 and the sun is above the horizon
  std::shared_ptr<const SkyTable> table;  // the dome tabulated (set by the make_* functions)
};

// The sky scaled by its zenith luminance, or by the dome's diffuse horizontal illuminance.
// `sun_direction` need not be unit (non-zero); `sun_normal_illuminance` is E_sun,n (0: no
// disc). Throws std::invalid_argument for a bad type or negative values.
SkyModel make_sky_from_zenith_luminance(int sky_type, Vec3 sun_direction, double zenith_luminance,
                                        double ground_albedo, double sun_normal_illuminance);
SkyModel make_sky_from_horizontal_illuminance(int sky_type, Vec3 sun_direction,
                                              double horizontal_illuminance, double ground_albedo,
                                              double sun_normal_illuminance);

// A Perez all-weather sky (formula kPerez) with the luminance coefficients a..e, scaled by the
// dome's diffuse horizontal illuminance; otherwise as make_sky_from_horizontal_illuminance.
// light/perez_sky.h computes the coefficients and illuminances from weather data.
SkyModel make_perez_sky_from_horizontal_illuminance(const CieSkyParameters& coefficients,
                                                    Vec3 sun_direction,
                                                    double horizontal_illuminance,
                                                    double ground_albedo,
                                                    double sun_normal_illuminance);

// Luminance (cd/m²) of the dome (dir.y >= 0) or ground (dir.y < 0), WITHOUT the sun disc: the
// continuous part that quadratures and cubemap averages handle.
double sky_diffuse_luminance(const SkyModel& sky, Vec3 dir);
// The same plus the sun disc: what an eye looking in `dir` would see.
double sky_luminance(const SkyModel& sky, Vec3 dir);

// sky_diffuse_luminance from the sky's table (the formula when it has none).
double tabulated_sky_luminance(const SkyModel& sky, Vec3 dir);
// Σ weights[k] · tabulated_sky_luminance(sky, directions[k]) (as many weights as directions):
// a cubemap texel's quadrature in one call.
double sky_weighted_sum(const SkyModel& sky, std::span<const Vec3> directions,
                        std::span<const double> weights);

}  // namespace relight
