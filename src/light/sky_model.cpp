// CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003), traditional CIE overcast sky,
// ground and sun disc; formulas and conventions in sky_model.h.
#include "light/sky_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "math/frame.h"
#include "math/legendre.h"

namespace relight {

namespace {

// ISO 15469 Table 1 (a, b, c, d, e) for types 1..15.
constexpr CieSkyParameters kCieSkies[15] = {
    {4.0, -0.70, 0, -1.0, 0.00},    // 1  overcast, steep gradation, azimuthal uniformity
    {4.0, -0.70, 2, -1.5, 0.15},    // 2  overcast, steep gradation, slight brightening to sun
    {1.1, -0.80, 0, -1.0, 0.00},    // 3  overcast, moderate gradation, azimuthal uniformity
    {1.1, -0.80, 2, -1.5, 0.15},    // 4  overcast, moderate gradation, slight brightening
    {0.0, -1.00, 0, -1.0, 0.00},    // 5  sky of uniform luminance
    {0.0, -1.00, 2, -1.5, 0.15},    // 6  partly cloudy, no gradation, slight brightening
    {0.0, -1.00, 5, -2.5, 0.30},    // 7  partly cloudy, no gradation, brighter circumsolar
    {0.0, -1.00, 10, -3.0, 0.45},   // 8  partly cloudy, no gradation, distinct solar corona
    {-1.0, -0.55, 2, -1.5, 0.15},   // 9  partly cloudy, obscured sun
    {-1.0, -0.55, 5, -2.5, 0.30},   // 10 partly cloudy, brighter circumsolar region
    {-1.0, -0.55, 10, -3.0, 0.45},  // 11 white-blue sky with distinct solar corona
    {-1.0, -0.32, 10, -3.0, 0.45},  // 12 CIE standard clear sky, low turbidity
    {-1.0, -0.32, 16, -3.0, 0.30},  // 13 CIE standard clear sky, polluted atmosphere
    {-1.0, -0.15, 16, -3.0, 0.30},  // 14 cloudless turbid sky with broad solar corona
    {-1.0, -0.15, 24, -2.8, 0.15},  // 15 white-blue turbid sky with broad solar corona
};

void check_type(int sky_type) {
  if (sky_type < 0 || sky_type > 15) {
    throw std::invalid_argument("CIE sky type must be 0 (traditional overcast) or 1..15, got " +
                                std::to_string(sky_type));
  }
}

// The angle between a sky element and the sun, and its cosine, from their unit directions.
// acos of the dot product: near the sun, where it is least accurate, a rounding of 1e-16 in
// the cosine moves the angle by 1.5e-8 rad, far below any feature of the sky (atan2 of the
// cross and dot products, accurate there too, cost the sky's cubemap a third of its time).
struct SunAngle {
  double chi, cos_chi;
};
SunAngle sun_angle(Vec3 dir, Vec3 sun) {
  const double c = std::clamp(dot(dir, sun), -1.0, 1.0);
  return {std::acos(c), c};
}

// The Perez formula's gradation and indicatrix (sky_model.h, SkyFormula).
double perez_gradation(const CieSkyParameters& p, double cos_zenith) {
  return 1.0 + p.a * std::exp(p.b / std::max(cos_zenith, kPerezMinCosZenith));
}
double perez_indicatrix(const CieSkyParameters& p, SunAngle g) {
  return 1.0 + p.c * std::exp(p.d * g.chi) + p.e * g.cos_chi * g.cos_chi;
}

// The dome's formula: which one, and its parameters.
struct Dome {
  SkyFormula formula = SkyFormula::kCie;
  int sky_type = 0;
  CieSkyParameters p;
};

// The dome's relative luminance in `dir`, with its normaliser.
double relative(const Dome& dome, double norm, Vec3 dir, Vec3 sun) {
  const double cos_z = std::max(dir.y, 0.0);
  if (dome.formula == SkyFormula::kPerez) {
    return std::max(perez_indicatrix(dome.p, sun_angle(dir, sun)) * perez_gradation(dome.p, cos_z),
                    0.0) *
           norm;
  }
  if (dome.sky_type == 0) return (1.0 + 2.0 * cos_z) / 3.0;
  return cie_indicatrix(dome.p, sun_angle(dir, sun).chi) * cie_gradation(dome.p, cos_z) * norm;
}

// 1 / (f(Zs)·φ(0)): the relative luminance at the zenith made 1.
double normaliser(const Dome& dome, Vec3 sun) {
  const double zs = std::acos(std::clamp(sun.y, -1.0, 1.0));
  if (dome.formula == SkyFormula::kPerez) {
    const double zenith =
        perez_indicatrix(dome.p, {zs, std::cos(zs)}) * perez_gradation(dome.p, 1.0);
    return zenith > kPerezMinZenith ? 1.0 / zenith : 1.0;
  }
  if (dome.sky_type == 0) return 1.0;
  return 1.0 / (cie_indicatrix(dome.p, zs) * cie_gradation(dome.p, 1.0));
}

Dome cie_dome(int sky_type) {
  check_type(sky_type);
  return {SkyFormula::kCie, sky_type,
          sky_type == 0 ? CieSkyParameters{} : cie_sky_parameters(sky_type)};
}
Dome dome_of(const SkyModel& sky) {
  return {sky.formula, sky.sky_type, sky.parameters};
}

// The dome's relative luminance (L/Lz, made 1 at the zenith by `norm`) as a SkyTable whose
// scale is `norm` (sky_model.h): the gradation and the indicatrix at kSkyTableIntervals + 1
// nodes each.
constexpr double kPerezMaxReciprocal = 1.0 / kPerezMinCosZenith;
constexpr double kSqrt2 = 1.4142135623730950488;

SkyTable tabulate(const Dome& dome, Vec3 sun, double norm) {
  SkyTable t;
  t.scale = norm;
  t.sun_direction = sun;
  t.perez = dome.formula == SkyFormula::kPerez;
  const auto nodes = static_cast<std::size_t>(kSkyTableIntervals) + 1;
  t.gradation.resize(nodes);
  t.toward_sun.resize(nodes);
  t.away_from_sun.resize(nodes);
  const auto indicatrix = [&](double chi, double cos_chi) {
    if (t.perez) return perez_indicatrix(dome.p, {chi, cos_chi});
    return dome.sky_type == 0 ? 1.0 : cie_indicatrix(dome.p, chi);
  };
  for (std::size_t k = 0; k < nodes; ++k) {
    const double q = static_cast<double>(k) / kSkyTableIntervals;
    if (t.perez) {
      t.gradation[k] = perez_gradation(dome.p, 1.0 / (1.0 + q * (kPerezMaxReciprocal - 1.0)));
    } else {
      t.gradation[k] = dome.sky_type == 0 ? (1.0 + 2.0 * q) / 3.0 : cie_gradation(dome.p, q);
    }
    // The chord |dir ∓ sun| = q·√2 at the angle 2·asin(q/√2) from the sun (or antisun).
    const double half = 2.0 * std::asin(q / kSqrt2);
    t.toward_sun[k] = indicatrix(half, 1.0 - q * q);
    t.away_from_sun[k] = indicatrix(kPi - half, q * q - 1.0);
  }
  return t;
}

// Linear interpolation in a table of kSkyTableIntervals + 1 nodes over q in [0, 1] (clamped).
[[gnu::always_inline]] inline double interpolate(const std::vector<double>& nodes, double q) {
  const double x = std::clamp(q, 0.0, 1.0) * kSkyTableIntervals;
  const int i = std::min(static_cast<int>(x), kSkyTableIntervals - 1);
  const auto k = static_cast<std::size_t>(i);
  return nodes[k] + (x - i) * (nodes[k + 1] - nodes[k]);
}

// The table's gradation at cos Z = y (>= 0) and its indicatrix (times its scale, the
// normaliser) toward the unit `dir`. Without branches on the direction (the sun's side, a coin toss
// over a cubemap, is a select), and inlined into the loops over many directions, which is several
// times faster than a call per direction (measured: docs/decisions.md).
[[gnu::always_inline]] inline double table_gradation(const SkyTable& t, double y) {
  return interpolate(
      t.gradation,
      t.perez ? (1.0 / std::max(y, kPerezMinCosZenith) - 1.0) / (kPerezMaxReciprocal - 1.0) : y);
}
[[gnu::always_inline]] inline double table_indicatrix(const SkyTable& t, Vec3 dir) {
  // |dir ∓ sun|/√2 = √(1 ∓ cos χ), toward the nearer of the sun and the antisun.
  const double c = dot(dir, t.sun_direction);
  const std::vector<double>& indicatrix = c >= 0 ? t.toward_sun : t.away_from_sun;
  return interpolate(indicatrix, std::sqrt(std::max(1.0 - std::abs(c), 0.0))) * t.scale;
}
// Their product: the relative luminance, for dir.y >= 0.
[[gnu::always_inline]] inline double table_value(const SkyTable& t, double gradation, Vec3 dir) {
  const double v = gradation * table_indicatrix(t, dir);
  return t.perez ? std::max(v, 0.0) : v;
}
[[gnu::always_inline]] inline double table_value(const SkyTable& t, Vec3 dir) {
  return table_value(t, table_gradation(t, std::max(dir.y, 0.0)), dir);
}

// Zenith nodes of the quadrature that scales a sky to its horizontal illuminance (twice as
// many in azimuth): a sky so scaled, integrated again at kZenithScalingNodes, is within 1.0e-7
// of its E_h for every CIE type and within 1.5e-4 for Perez skies (whose guards put kinks into the
// integrand), suns 2°–85° (measured over the tabulated dome: 16 types × 5 suns, 100 weathers); a
// quarter of the cost of 192 × 384, which a moving sun pays every frame and `relight annual` every
// hour.
constexpr int kNormalisationNodes = 96;
// The rule of a sky scaled by its zenith luminance (sky_relative_horizontal_illuminance's
// default in sky_model.h): that integral is paid once per sky made, not per frame.
constexpr int kZenithScalingNodes = 192;

// ∫ (L/Lz) cos Z dω over the dome, by sky_dome_quadrature's rule over the dome's table. The
// rule is rings of equal zenith angle, each two half turns of azimuth from the sun's meridian
// that mirror each other (the Gauss–Legendre nodes are symmetric), and the dome is symmetric
// about that meridian: per ring the gradation once, and one half turn counted twice.
double relative_horizontal_illuminance(const SkyTable& table, int n_zenith, int n_azimuth) {
  const DomeRule rule = sky_dome_rule(table.sun_direction, n_zenith, n_azimuth);
  const std::size_t half_turn = rule.azimuth_weight.size() / 2;
  double total = 0;
  for (std::size_t k = 0; k < rule.zenith_weight.size(); ++k) {
    const double mu = rule.zenith_cos[k], s = rule.zenith_sin[k];
    const double g = table_gradation(table, mu);
    double ring = 0;
    for (std::size_t j = 0; j < half_turn; ++j) {
      const Vec3 d{s * rule.azimuth_sin[j], mu, -s * rule.azimuth_cos[j]};
      ring += rule.azimuth_weight[j] * table_value(table, g, d);
    }
    total += 2 * rule.zenith_weight[k] * mu * ring;
  }
  return total;
}

// The unit sun direction; std::invalid_argument unless finite and non-zero.
Vec3 unit_sun_direction(Vec3 sun_direction) {
  if (!(length(sun_direction) > 0) || !is_finite(sun_direction)) {
    throw std::invalid_argument("sun direction must be finite and non-zero");
  }
  return normalize(sun_direction);
}

// The integral a sky is scaled by: relative_horizontal_illuminance at kNormalisationNodes.
double normalisation_integral(const SkyModel& sky) {
  return relative_horizontal_illuminance(*sky.table, kNormalisationNodes, 2 * kNormalisationNodes);
}

SkyModel make_sky(const Dome& dome, Vec3 sun_direction, double ground_albedo,
                  double sun_normal_illuminance) {
  const Vec3 sun = unit_sun_direction(sun_direction);
  if (!(ground_albedo >= 0 && ground_albedo <= 1)) {
    throw std::invalid_argument("ground albedo must lie in 0..1");
  }
  if (!(sun_normal_illuminance >= 0) || !std::isfinite(sun_normal_illuminance)) {
    throw std::invalid_argument("sun illuminance must be finite and >= 0");
  }
  SkyModel sky;
  sky.formula = dome.formula;
  sky.sky_type = dome.sky_type;
  sky.parameters = dome.p;
  sky.sun_direction = sun;
  sky.indicatrix_normaliser = normaliser(dome, sky.sun_direction);
  sky.table = std::make_shared<const SkyTable>(
      tabulate(dome, sky.sun_direction, sky.indicatrix_normaliser));
  sky.ground_albedo = ground_albedo;
  if (sun_normal_illuminance > 0 && sky.sun_direction.y > 0) {
    sky.sun = make_sun_disc(sky.sun_direction, sun_normal_illuminance);
    sky.sun_horizontal_illuminance = sun_normal_illuminance * sky.sun_direction.y;
  }
  return sky;
}

void finish(SkyModel& sky) {
  sky.ground_luminance =
      sky.ground_albedo * (sky.sky_horizontal_illuminance + sky.sun_horizontal_illuminance) / kPi;
}

// The sky scaled by the dome's horizontal illuminance. A Perez dome whose coefficients light no
// direction of it becomes a uniform dome.
SkyModel sky_from_horizontal_illuminance(Dome dome, Vec3 sun_direction,
                                         double horizontal_illuminance, double ground_albedo,
                                         double sun_normal_illuminance) {
  if (!(horizontal_illuminance >= 0) || !std::isfinite(horizontal_illuminance)) {
    throw std::invalid_argument("horizontal illuminance must be finite and >= 0");
  }
  SkyModel sky = make_sky(dome, sun_direction, ground_albedo, sun_normal_illuminance);
  double integral = normalisation_integral(sky);
  if (dome.formula == SkyFormula::kPerez && !(integral > 0)) {
    dome.p = CieSkyParameters{};
    sky = make_sky(dome, sun_direction, ground_albedo, sun_normal_illuminance);
    integral = normalisation_integral(sky);
  }
  sky.zenith_luminance = horizontal_illuminance / integral;
  sky.sky_horizontal_illuminance = horizontal_illuminance;
  finish(sky);
  return sky;
}

}  // namespace

CieSkyParameters cie_sky_parameters(int type) {
  if (type < 1 || type > 15) {
    throw std::invalid_argument("CIE standard sky type must be 1..15, got " + std::to_string(type));
  }
  return kCieSkies[type - 1];
}

double cie_gradation(const CieSkyParameters& p, double cos_zenith) {
  if (!(cos_zenith > 0)) return 1.0;
  return 1.0 + p.a * std::exp(p.b / cos_zenith);
}

double cie_indicatrix(const CieSkyParameters& p, double chi) {
  const double c = std::cos(chi);
  return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * kPi / 2.0)) + p.e * c * c;
}

double sky_relative_luminance(int sky_type, Vec3 dir, Vec3 sun_dir) {
  const Dome dome = cie_dome(sky_type);
  return relative(dome, normaliser(dome, sun_dir), dir, sun_dir);
}

DomeRule sky_dome_rule(Vec3 sun_dir, int n_zenith, int n_azimuth) {
  if (n_zenith < 1 || n_azimuth < 1) {
    throw std::invalid_argument("quadrature needs at least one node per dimension");
  }
  const Vec3 sun = normalize(sun_dir);
  // Panels in the zenith angle Z: [0, Zs] and [Zs, 90°] when the sun is strictly inside.
  struct Panel {
    double lo, hi;
    int n;
  };
  std::vector<Panel> panels;
  const double zs = std::acos(std::clamp(sun.y, -1.0, 1.0));
  const double horizon = kPi / 2;
  constexpr int kMinPanelNodes = 4;
  if (zs > 0 && zs < horizon && n_zenith >= 2 * kMinPanelNodes) {
    const int low = std::clamp(static_cast<int>(std::lround(n_zenith * zs / horizon)),
                               kMinPanelNodes, n_zenith - kMinPanelNodes);
    panels = {{0.0, zs, low}, {zs, horizon, n_zenith - low}};
  } else {
    panels = {{0.0, horizon, n_zenith}};
  }
  DomeRule rule;
  // Azimuth: Gauss–Legendre on each half turn [0, π] and [π, 2π] from the sun's azimuth. The
  // sky is symmetric about the sun's meridian; on each half the integrand is smooth up to that
  // meridian, and the nodes cluster toward it, i.e. toward the circumsolar peak.
  const double sun_azimuth = std::atan2(sun.x, -sun.z);
  const int n_half = (n_azimuth + 1) / 2;
  const GaussLegendre& gl_az = gauss_legendre(n_half);
  for (int half = 0; half < 2; ++half) {
    for (int j = 0; j < n_half; ++j) {
      const double az = sun_azimuth + kPi * (half + 0.5 * (gl_az.nodes[j] + 1.0));
      rule.azimuth_sin.push_back(std::sin(az));
      rule.azimuth_cos.push_back(std::cos(az));
      rule.azimuth_weight.push_back(0.5 * kPi * gl_az.weights[j]);
    }
  }
  for (const Panel& panel : panels) {
    const GaussLegendre& gl = gauss_legendre(panel.n);
    const double half = 0.5 * (panel.hi - panel.lo), mid = 0.5 * (panel.hi + panel.lo);
    for (int k = 0; k < panel.n; ++k) {
      const double z = mid + half * gl.nodes[k];
      rule.zenith_sin.push_back(std::sin(z));
      rule.zenith_cos.push_back(std::cos(z));
      rule.zenith_weight.push_back(half * gl.weights[k] * std::sin(z));  // dω = sin Z dZ dφ
    }
  }
  return rule;
}

DomeQuadrature sky_dome_quadrature(Vec3 sun_dir, int n_zenith, int n_azimuth) {
  const DomeRule r = sky_dome_rule(sun_dir, n_zenith, n_azimuth);
  DomeQuadrature rule;
  rule.directions.reserve(r.zenith_weight.size() * r.azimuth_weight.size());
  rule.weights.reserve(rule.directions.capacity());
  for (std::size_t k = 0; k < r.zenith_weight.size(); ++k) {
    const double s = r.zenith_sin[k], mu = r.zenith_cos[k];
    for (std::size_t j = 0; j < r.azimuth_weight.size(); ++j) {
      rule.directions.push_back({s * r.azimuth_sin[j], mu, -s * r.azimuth_cos[j]});
      rule.weights.push_back(r.zenith_weight[k] * r.azimuth_weight[j]);
    }
  }
  return rule;
}

double sky_relative_horizontal_illuminance(int sky_type, Vec3 sun_dir, int n_zenith,
                                           int n_azimuth) {
  const Dome dome = cie_dome(sky_type);
  const Vec3 sun = normalize(sun_dir);
  return relative_horizontal_illuminance(tabulate(dome, sun, normaliser(dome, sun)), n_zenith,
                                         n_azimuth);
}

Vec3 sun_disc_direction(const SunDisc& disc, double x, double y) {
  const Frame frame = frame_from_normal(disc.direction);
  const double t = disc.tan_angular_radius;
  return normalize(frame.to_world({x * t, y * t, 1}));
}

std::vector<Vec3> sun_disc_spiral(const SunDisc& disc, int count) {
  const double golden = kPi * (3 - std::sqrt(5.0));
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    const double radius = std::sqrt((i + 0.5) / count), a = golden * i;
    out.push_back(sun_disc_direction(disc, radius * std::cos(a), radius * std::sin(a)));
  }
  return out;
}

SunDisc make_sun_disc(Vec3 direction, double normal_illuminance) {
  return make_source_disc(direction, radians(kSunAngularDiameterDeg) / 2.0, normal_illuminance);
}

SunDisc make_source_disc(Vec3 direction, double angular_radius, double normal_illuminance) {
  SunDisc d;
  d.direction = normalize(direction);
  d.angular_radius = angular_radius;
  d.cos_angular_radius = std::cos(d.angular_radius);
  d.tan_angular_radius = std::tan(d.angular_radius);
  const double s = std::sin(d.angular_radius);
  // 1 − cos r = 2 sin²(r/2), without cancellation.
  const double h = std::sin(d.angular_radius / 2.0);
  d.solid_angle = 4.0 * kPi * h * h;
  d.normal_illuminance = normal_illuminance;
  d.luminance = normal_illuminance / (kPi * s * s);
  return d;
}

double sun_disc_luminance(const SunDisc& disc, Vec3 dir) {
  return dot(dir, disc.direction) >= disc.cos_angular_radius ? disc.luminance : 0.0;
}

SkyModel make_sky_from_zenith_luminance(int sky_type, Vec3 sun_direction, double zenith_luminance,
                                        double ground_albedo, double sun_normal_illuminance) {
  if (!(zenith_luminance >= 0) || !std::isfinite(zenith_luminance)) {
    throw std::invalid_argument("zenith luminance must be finite and >= 0");
  }
  SkyModel sky = make_sky(cie_dome(sky_type), sun_direction, ground_albedo, sun_normal_illuminance);
  sky.zenith_luminance = zenith_luminance;
  sky.sky_horizontal_illuminance =
      zenith_luminance *
      relative_horizontal_illuminance(*sky.table, kZenithScalingNodes, 2 * kZenithScalingNodes);
  finish(sky);
  return sky;
}

SkyModel make_sky_from_horizontal_illuminance(int sky_type, Vec3 sun_direction,
                                              double horizontal_illuminance, double ground_albedo,
                                              double sun_normal_illuminance) {
  return sky_from_horizontal_illuminance(cie_dome(sky_type), sun_direction, horizontal_illuminance,
                                         ground_albedo, sun_normal_illuminance);
}

SkyModel make_perez_sky_from_horizontal_illuminance(const CieSkyParameters& coefficients,
                                                    Vec3 sun_direction,
                                                    double horizontal_illuminance,
                                                    double ground_albedo,
                                                    double sun_normal_illuminance) {
  return sky_from_horizontal_illuminance({SkyFormula::kPerez, 0, coefficients}, sun_direction,
                                         horizontal_illuminance, ground_albedo,
                                         sun_normal_illuminance);
}

double sky_diffuse_luminance(const SkyModel& sky, Vec3 dir) {
  if (dir.y < 0) return sky.ground_luminance;
  return sky.zenith_luminance *
         relative(dome_of(sky), sky.indicatrix_normaliser, dir, sky.sun_direction);
}

double tabulated_sky_luminance(const SkyModel& sky, Vec3 dir) {
  if (dir.y < 0) return sky.ground_luminance;
  return sky.table ? sky.zenith_luminance * table_value(*sky.table, dir)
                   : sky_diffuse_luminance(sky, dir);
}

double sky_weighted_sum(const SkyModel& sky, std::span<const Vec3> directions,
                        std::span<const double> weights) {
  double sum = 0;
  if (!sky.table) {
    for (std::size_t k = 0; k < directions.size(); ++k) {
      sum += weights[k] * sky_diffuse_luminance(sky, directions[k]);
    }
    return sum;
  }
  const SkyTable& table = *sky.table;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const Vec3 d = directions[k];
    sum += weights[k] *
           (d.y < 0 ? sky.ground_luminance : sky.zenith_luminance * table_value(table, d));
  }
  return sum;
}

double sky_luminance(const SkyModel& sky, Vec3 dir) {
  double l = sky_diffuse_luminance(sky, dir);
  if (sky.sun) l += sun_disc_luminance(*sky.sun, dir);
  return l;
}

}  // namespace relight
