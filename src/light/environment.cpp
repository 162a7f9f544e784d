// Environments: evaluation, SH projection (Funk–Hecke for the spherical caps of ground and sun
// disc) and cubemap rasterisation; see environment.h.
#include "light/environment.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "light/daylight_availability.h"
#include "light/environment_map_cubemap.h"
#include "light/perez_sky.h"
#include "light/sun_position.h"
#include "math/cubemap.h"
#include "math/equirect.h"
#include "math/legendre.h"
#include "math/sh.h"
#include "math/tabulated.h"

namespace relight {

namespace {

Rgb grey(double v) {
  return {v, v, v};
}

Rgb map_lookup(const EquirectMap& map, const MapRotation& rot, double scale, Vec3 dir) {
  const EquirectTexel t = equirect_texel(map.width, map.height, rot.to_map(dir));
  return map.texels[static_cast<std::size_t>(t.j) * map.width + t.i] * scale;
}

// Funk–Hecke: SH of a uniform cap (luminance L, cos of the angular radius cos_rho, axis a) is
// c_lm = L·2π·∫_{cos ρ}^{1} P_l(t) dt · Y_lm(a). Added to `out`.
void add_cap(int order, Vec3 axis, double cos_rho, double luminance, std::span<double> out) {
  std::vector<double> y(sh_count(order));
  sh_eval(order, axis, y);
  std::vector<double> p(order + 1);
  legendre_all(cos_rho, p);
  for (int l = 0; l < order; ++l) {
    // ∫_{c}^{1} P_l = (P_{l−1}(c) − P_{l+1}(c))/(2l+1) for l >= 1 (from (2l+1)P_l = P'_{l+1} −
    // P'_{l−1} and P_l(1) = 1).
    const double integral = l == 0 ? 1.0 - cos_rho : (p[l - 1] - p[l + 1]) / (2 * l + 1);
    const double k = luminance * 2.0 * kPi * integral;
    for (int m = -l; m <= l; ++m) out[sh_index(l, m)] += k * y[sh_index(l, m)];
  }
}

std::vector<Rgb> sky_sh(const SkyModel& sky, int order) {
  std::vector<double> c(sh_count(order), 0.0);
  const DomeQuadrature rule = sky_dome_quadrature(sky.sun_direction, std::max(64, order + 32),
                                                  std::max(128, 2 * order + 64));
  for (std::size_t i = 0; i < rule.weights.size(); ++i) {
    const Vec3 d = rule.directions[i];
    sh_add_sample(d, tabulated_sky_luminance(sky, d) * rule.weights[i], std::span<double>(c));
  }
  // Ground: the cap of angular radius 90° about −y.
  add_cap(order, {0, -1, 0}, 0.0, sky.ground_luminance, c);
  if (sky.sun)
    add_cap(order, sky.sun->direction, sky.sun->cos_angular_radius, sky.sun->luminance, c);
  std::vector<Rgb> out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) out[i] = grey(c[i]);
  return out;
}

std::vector<Rgb> map_sh(const Environment& env, int order) {
  const EquirectMap& map = *env.map;
  const MapRotation rot(env.rotate_deg);
  std::vector<Rgb> c(sh_count(order));
  for (int j = 0; j < map.height; ++j) {
    const double w = equirect_row_solid_angle(map.width, map.height, j) * env.scale;
    for (int i = 0; i < map.width; ++i) {
      const Rgb v = map.texels[static_cast<std::size_t>(j) * map.width + i];
      if (v.r == 0 && v.g == 0 && v.b == 0) continue;
      sh_add_sample(rot.to_world(equirect_texel_direction(map.width, map.height, i, j)), v * w,
                    std::span<Rgb>(c));
    }
  }
  return c;
}

// Gauss–Legendre points per texel and axis for a face of n texels: at least 3, and about 48
// across a face. The texel's mean radiance is Σ w·J·f / Σ w·J (a constant sky exactly). Against
// 32 × 32 midpoint sub-cells, for six Perez skies (suns 10°–70° high, overcast to clear) at n = 32,
// the worst texel error per sky is 2.7e-4…1.2e-3 — near the sun and at the gradation's guard 5.7°
// above the horizon, where the sky has a kink — never above that of the 4 × 4 midpoint
// sub-cells it replaced (3.0e-4…1.3e-3), from 9 evaluations instead of 16 (a sky's cubemap is
// most of a shell, which `relight annual` makes for every hour of a year).
int texel_gauss_points(int n) {
  return std::max(3, (48 + n - 1) / n);
}

// The sky's texel quadrature of a face size: per texel above the horizon its points (unit
// directions) and weights w·J, by the product Gauss–Legendre rule in u and v with the solid
// angle's Jacobian dω = du dv / (1 + u² + v²)^{3/2}; a texel the horizon crosses split there.
// Texels wholly below the horizon (which see the uniform ground) have no points. The same for
// every sky: tabulated once per face size, so that a sky's cubemap evaluates only the sky.
struct SkyTexelRule {
  std::vector<std::uint32_t> first;  // texel t's points are [first[t], first[t + 1])
  std::vector<Vec3> directions;
  std::vector<double> weights;
  std::vector<double> solid_angle;  // Σ w·J per texel
  std::vector<bool> below;
};

void add_gauss_rect(int face, double u0, double u1, double v0, double v1, const GaussLegendre& rule,
                    SkyTexelRule& out) {
  const double hu = 0.5 * (u1 - u0), hv = 0.5 * (v1 - v0);
  for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
    const double v = v0 + hv * (rule.nodes[b] + 1.0);
    for (std::size_t a = 0; a < rule.nodes.size(); ++a) {
      const double u = u0 + hu * (rule.nodes[a] + 1.0);
      const double r2 = 1.0 + u * u + v * v;
      out.weights.push_back(rule.weights[a] * rule.weights[b] * hu * hv / (r2 * std::sqrt(r2)));
      out.directions.push_back(cubemap_direction({face, 0.5 * u + 0.5, 0.5 * v + 0.5}));
    }
  }
}

SkyTexelRule tabulate_sky_texel_rule(int n) {
  const GaussLegendre& rule = gauss_legendre(texel_gauss_points(n));
  SkyTexelRule out;
  const std::size_t texels = cubemap_texel_count(n);
  out.first.reserve(texels + 1);
  out.solid_angle.assign(texels, 0.0);
  out.below.assign(texels, false);
  for (std::size_t t = 0; t < texels; ++t) {
    out.first.push_back(static_cast<std::uint32_t>(out.weights.size()));
    const CubemapTexel c = cubemap_texel_from_index(n, t);
    const bool side = c.face != kPosY && c.face != kNegY;  // y = −v on the four side faces
    const double v0 = 2.0 * c.j / n - 1.0, v1 = 2.0 * (c.j + 1) / n - 1.0;
    const double u0 = 2.0 * c.i / n - 1.0, u1 = 2.0 * (c.i + 1) / n - 1.0;
    if (c.face == kNegY || (side && v0 >= 0)) {
      out.below[t] = true;
    } else if (side && v0 < 0 && v1 > 0) {  // the horizon crosses the texel: split it there
      add_gauss_rect(c.face, u0, u1, v0, 0.0, rule, out);
      add_gauss_rect(c.face, u0, u1, 0.0, v1, rule, out);
    } else {
      add_gauss_rect(c.face, u0, u1, v0, v1, rule, out);
    }
    for (std::size_t k = out.first.back(); k < out.weights.size(); ++k) {
      out.solid_angle[t] += out.weights[k];
    }
  }
  out.first.push_back(static_cast<std::uint32_t>(out.weights.size()));
  return out;
}

const SkyTexelRule& sky_texel_rule(int n) {
  return tabulated<SkyTexelRule>(n, [](int size) { return tabulate_sky_texel_rule(size); });
}

std::vector<Rgb> sky_cubemap(const SkyModel& sky, int n) {
  const SkyTexelRule& rule = sky_texel_rule(n);
  const std::vector<double>& omega = cubemap_solid_angles(n);
  std::vector<Rgb> out(cubemap_texel_count(n));
  // Rows of texels are independent (the run time rebuilds a shell per sky change: use every
  // core).
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, 6 * static_cast<std::size_t>(n)),
      [&](const tbb::blocked_range<std::size_t>& rows) {
        for (std::size_t t = rows.begin() * n; t != rows.end() * n; ++t) {
          if (rule.below[t]) {
            out[t] = grey(sky.ground_luminance);
            continue;
          }
          const std::size_t first = rule.first[t], count = rule.first[t + 1] - first;
          out[t] = grey(sky_weighted_sum(sky, std::span(rule.directions).subspan(first, count),
                                         std::span(rule.weights).subspan(first, count)) /
                        rule.solid_angle[t]);
        }
      });
  if (sky.sun) {
    const CubemapTexel t = cubemap_texel(n, sky.sun->direction);
    out[cubemap_texel_index(n, t)] += grey(sky.sun->integrated_luminance() / omega[t.j * n + t.i]);
  }
  return out;
}

}  // namespace

Rgb Environment::diffuse_radiance(Vec3 dir) const {
  switch (kind) {
    case EnvironmentKind::kUniform:
      return uniform_radiance;
    case EnvironmentKind::kMap:
      return map_lookup(*map, MapRotation(rotate_deg), scale, dir);
    case EnvironmentKind::kSky:
      return grey(sky_diffuse_luminance(sky, dir));
  }
  return {};
}

Rgb Environment::radiance(Vec3 dir) const {
  Rgb l = diffuse_radiance(dir);
  if (kind == EnvironmentKind::kSky && sky.sun) l += grey(sun_disc_luminance(*sky.sun, dir));
  return l;
}

const std::optional<SunDisc>& Environment::sun() const {
  static const std::optional<SunDisc> kNone;
  return kind == EnvironmentKind::kSky ? sky.sun : kNone;
}

Environment make_uniform_environment(Rgb radiance) {
  Environment env;
  env.kind = EnvironmentKind::kUniform;
  env.uniform_radiance = radiance;
  return env;
}

Environment make_map_environment(std::shared_ptr<const EquirectMap> map, double rotate_deg,
                                 double scale) {
  if (!map || map->width < 1 || map->height < 1 ||
      map->texels.size() != static_cast<std::size_t>(map->width) * map->height) {
    throw std::invalid_argument("environment map must hold width·height > 0 texels");
  }
  if (!(scale >= 0) || !std::isfinite(scale) || !std::isfinite(rotate_deg)) {
    throw std::invalid_argument("map scale must be finite and >= 0, rotation finite");
  }
  Environment env;
  env.kind = EnvironmentKind::kMap;
  env.map = std::move(map);
  env.rotate_deg = rotate_deg;
  env.scale = scale;
  return env;
}

Environment make_sky_environment(SkyModel sky) {
  Environment env;
  env.kind = EnvironmentKind::kSky;
  env.sky = sky;
  return env;
}

Vec3 sun_direction(const SunSpec& sun, double north_deg) {
  switch (sun.placement) {
    case SunPlacement::kPlaceAndTime: {
      const CivilDateTime& t = sun.local_time;
      const UtcTime utc =
          utc_from_local(t.year, t.month, t.day, t.hour, t.minute, t.second, sun.utc_offset_hours);
      const SunPosition p = psa_sun_position(utc, sun.latitude_deg, sun.longitude_deg);
      return horizontal_to_world(p.azimuth_deg + north_deg, p.altitude_deg());
    }
    case SunPlacement::kAngles:
      return horizontal_to_world(sun.azimuth_deg + north_deg, sun.altitude_deg);
    case SunPlacement::kNone:
      break;
  }
  throw std::invalid_argument("the sun has no position");
}

int sun_day_of_year(const SunSpec& sun) {
  return sun.placement == SunPlacement::kPlaceAndTime ? day_of_year(sun.local_time) : 0;
}

Environment make_environment(const EnvironmentSpec& spec, std::shared_ptr<const EquirectMap> map) {
  switch (spec.type) {
    case EnvironmentType::kUniform: {
      const double y = luminance(spec.color);
      return make_uniform_environment(y > 0 ? spec.color * (spec.luminance / y) : Rgb{});
    }
    case EnvironmentType::kMap:
      if (!map) throw std::invalid_argument(spec.where + ": the map image was not loaded");
      return make_map_environment(std::move(map), spec.rotate_deg + spec.north_deg, spec.scale);
    case EnvironmentType::kCieSky: {
      const Vec3 sun = spec.sun.placement == SunPlacement::kNone
                           ? Vec3{0, 1, 0}
                           : sun_direction(spec.sun, spec.north_deg);
      switch (spec.scaling) {
        case SkyScaling::kZenithLuminance:
          return make_sky_environment(make_sky_from_zenith_luminance(
              spec.sky_type, sun, spec.scaling_value, spec.ground_albedo, spec.sun_illuminance));
        case SkyScaling::kHorizontalIlluminance:
          return make_sky_environment(make_sky_from_horizontal_illuminance(
              spec.sky_type, sun, spec.scaling_value, spec.ground_albedo, spec.sun_illuminance));
        case SkyScaling::kSunAltitude: {
          const DaylightAvailability day =
              cie_sky_daylight(spec.sky_type, sun, sun_day_of_year(spec.sun), spec.elevation_m,
                               spec.linke_turbidity);
          return make_sky_environment(make_sky_from_horizontal_illuminance(
              spec.sky_type, sun, day.sky_horizontal_illuminance, spec.ground_albedo,
              spec.sun_illuminance_from_model ? day.sun_normal_illuminance : spec.sun_illuminance));
        }
      }
      break;
    }
    case EnvironmentType::kPerezSky: {
      const PerezWeather weather{spec.direct_normal_irradiance, spec.diffuse_horizontal_irradiance,
                                 spec.dew_point_c, sun_day_of_year(spec.sun)};
      return make_sky_environment(
          make_perez_sky(weather, sun_direction(spec.sun, spec.north_deg), spec.ground_albedo));
    }
  }
  throw std::invalid_argument("unknown environment type");
}

std::vector<Rgb> environment_sh(const Environment& env, int order) {
  if (order < 1) throw std::invalid_argument("SH order must be >= 1");
  switch (env.kind) {
    case EnvironmentKind::kUniform: {
      std::vector<Rgb> c(sh_count(order));
      c[0] = env.uniform_radiance * std::sqrt(4.0 * kPi);
      return c;
    }
    case EnvironmentKind::kMap:
      return map_sh(env, order);
    case EnvironmentKind::kSky:
      return sky_sh(env.sky, order);
  }
  return {};
}

std::vector<Rgb> environment_cubemap(const Environment& env, int face_size) {
  if (face_size < 1) throw std::invalid_argument("cubemap face size must be >= 1");
  switch (env.kind) {
    case EnvironmentKind::kUniform:
      return std::vector<Rgb>(cubemap_texel_count(face_size), env.uniform_radiance);
    case EnvironmentKind::kMap:
      return equirect_map_to_cubemap(*env.map, env.rotate_deg, env.scale, face_size);
    case EnvironmentKind::kSky:
      return sky_cubemap(env.sky, face_size);
  }
  return {};
}

Rgb environment_integral(const Environment& env) {
  switch (env.kind) {
    case EnvironmentKind::kUniform:
      return env.uniform_radiance * (4.0 * kPi);
    case EnvironmentKind::kMap: {
      const EquirectMap& map = *env.map;
      Rgb sum;
      for (int j = 0; j < map.height; ++j) {
        Rgb row;
        for (int i = 0; i < map.width; ++i) {
          row += map.texels[static_cast<std::size_t>(j) * map.width + i];
        }
        sum += row * equirect_row_solid_angle(map.width, map.height, j);
      }
      return sum * env.scale;
    }
    case EnvironmentKind::kSky: {
      const SkyModel& sky = env.sky;
      const DomeQuadrature rule = sky_dome_quadrature(sky.sun_direction, 192, 384);
      const double dome = sky_weighted_sum(sky, rule.directions, rule.weights);
      double total = dome + sky.ground_luminance * 2.0 * kPi;
      if (sky.sun) total += sky.sun->integrated_luminance();
      return grey(total);
    }
  }
  return {};
}

}  // namespace relight
