#include "sources/luminaires/luminaire_direct.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "engine/transfer_blocks.h"

namespace relight {

namespace {

bool is_round(OpeningShape s) {
  switch (s) {
    case OpeningShape::kCircular:
    case OpeningShape::kEllipse:
    case OpeningShape::kVerticalCylinder:
    case OpeningShape::kVerticalEllipticalCylinder:
    case OpeningShape::kSphere:
    case OpeningShape::kEllipsoidalSpheroid:
      return true;
    default:
      return false;
  }
}

}  // namespace

std::vector<Vec3> opening_sample_offsets(const LuminousOpening& opening,
                                         const PhotometricFrame& frame, int samples) {
  const double length = opening.length_m, width = opening.width_m, height = opening.height_m;
  if (samples <= 1 || opening.shape == OpeningShape::kPoint ||
      (length <= 0 && width <= 0 && height <= 0)) {
    return {Vec3{}};
  }
  // n × n stratified cells over the plan (C0 × C90), cell centres, optionally stacked in
  // height; round openings keep the cells whose centre lies inside the ellipse.
  const int layers = height > 0 ? 2 : 1;
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(samples / double(layers)))));
  std::vector<Vec3> out;
  for (int layer = 0; layer < layers; ++layer) {
    const double h = layers == 1 ? 0 : height * ((layer + 0.5) / layers - 0.5);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double s = (i + 0.5) / n - 0.5, t = (j + 0.5) / n - 0.5;  // in [-½, ½]
        if (is_round(opening.shape) && 4 * (s * s + t * t) > 1) continue;
        out.push_back(frame.c0 * (s * length) + frame.c90 * (t * width) - frame.aim * h);
      }
    }
  }
  if (out.empty()) out.push_back({});
  return out;
}

LuminousOpening luminaire_opening(const Luminaire& l, const LuminousOpening& from_file) {
  if (!l.has_size) return from_file;
  return {l.size.z > 0 ? OpeningShape::kRectangularWithLuminousSides : OpeningShape::kRectangular,
          l.size.x, l.size.y, l.size.z};
}

namespace {

// Whether the opening point at `offset` is seen from `origin` (already off its surface).
bool sees_opening_point(const Occluders& occluders, Vec3 origin, Vec3 luminaire_position,
                        Vec3 offset, std::uint64_t& rays) {
  const Vec3 to_light = luminaire_position + offset - origin;
  const double span = length(to_light);
  ++rays;
  return span <= kLightMargin ||
         !occluders.occluded({origin, to_light / span, 0, span - kLightMargin});
}

}  // namespace

DirectFactor direct_factor(const Occluders& occluders, Vec3 p, Vec3 normal, Vec3 luminaire_position,
                           const std::vector<Vec3>& opening_offsets, std::uint64_t& rays) {
  const Vec3 d = p - luminaire_position;
  const double dist = length(d);
  DirectFactor out{dist > 0 ? d / dist : Vec3{0, -1, 0}, 0};
  const double geometry = direct_geometry(p, normal, luminaire_position);
  if (geometry <= 0) return out;
  // Visible fraction of the opening, seen from the point.
  const Vec3 origin = offset_from_surface(p, normal);
  int visible = 0;
  for (const Vec3& offset : opening_offsets) {
    if (sees_opening_point(occluders, origin, luminaire_position, offset, rays)) ++visible;
  }
  out.factor = static_cast<double>(visible) / opening_offsets.size() * geometry;
  return out;
}

double direct_geometry(Vec3 p, Vec3 n, Vec3 luminaire_position) {
  const Vec3 d = p - luminaire_position;
  const double dist = length(d);
  if (dist <= kLightMargin) return 0;
  const double cos_receiver = -dot(n, d / dist);
  return cos_receiver > 0 ? cos_receiver / (dist * dist) : 0;
}

OpeningMask visible_opening_points(const Occluders& occluders, Vec3 p, Vec3 n,
                                   Vec3 luminaire_position,
                                   const std::vector<Vec3>& opening_offsets,
                                   const OpeningMask& candidates, std::uint64_t& rays) {
  if (opening_offsets.size() > kMaxOpeningMask) {
    throw std::invalid_argument("visible_opening_points: too many opening points");
  }
  const Vec3 origin = offset_from_surface(p, n);
  OpeningMask out{};
  for (std::size_t i = 0; i < opening_offsets.size(); ++i) {
    const std::uint64_t bit = std::uint64_t{1} << (i % 64);
    if ((candidates[i / 64] & bit) != 0 &&
        sees_opening_point(occluders, origin, luminaire_position, opening_offsets[i], rays)) {
      out[i / 64] |= bit;
    }
  }
  return out;
}

OpeningMask all_opening_points(std::size_t count) {
  OpeningMask out{};
  for (std::size_t i = 0; i < std::min(count, kMaxOpeningMask); ++i) {
    out[i / 64] |= std::uint64_t{1} << (i % 64);
  }
  return out;
}

int opening_point_count(const OpeningMask& mask) {
  int count = 0;
  for (const std::uint64_t word : mask) count += std::popcount(word);
  return count;
}

Rgb luminaire_direct_irradiance(const Occluders& occluders, std::span<const LuminaireLight> lights,
                                Vec3 p, Vec3 n) {
  Rgb e;
  std::uint64_t rays = 0;
  for (const LuminaireLight& l : lights) {
    if (max_component(l.rgb) <= 0) continue;
    const DirectFactor f = direct_factor(occluders, p, n, l.position, l.opening, rays);
    if (f.factor <= 0) continue;
    e += luminaire_irradiance(l, f.direction, f.factor);
  }
  return e;
}

double projected_opening_area(const LuminousOpening& o, Vec3 u) {
  const double w = o.width_m, l = o.length_m, h = o.height_m;
  const double side = std::sqrt(u.x * u.x + u.y * u.y);
  switch (o.shape) {
    case OpeningShape::kPoint:
      return 0;
    case OpeningShape::kRectangular:
    case OpeningShape::kRectangularWithLuminousSides:
      return w * l * std::abs(u.z) + h * (w * std::abs(u.x) + l * std::abs(u.y));
    default:  // round shapes: an ellipse of axes l × w, a cylinder of height h about it
      return kPi / 4 * w * l * std::abs(u.z) + 0.5 * (w + l) * h * side;
  }
}

SeenLight luminaire_seen_from(const Occluders& occluders, const LuminaireLight& light,
                              const LuminousOpening& opening, Vec3 p, Vec3 n, bool with_luminance) {
  SeenLight out;
  out.irradiance = luminaire_direct_irradiance(occluders, std::span(&light, 1), p, n);
  const Vec3 to = light.position - p;
  const double r = length(to);
  if (!(r > kLightMargin)) return out;
  out.direction = to / r;
  if (!with_luminance || max_component(light.rgb) <= 0 || dot(out.direction, n) <= 0) return out;
  if (occluders.occluded(Ray{p, out.direction, 0, r - kLightMargin})) return out;
  const Vec3 u = light.frame.to_photometric(out.direction * -1.0);
  const double intensity = luminance(light.rgb) * light.distribution->intensity(u);
  if (!(intensity > 0)) return out;
  out.in_view = true;
  const double area = projected_opening_area(opening, u);
  if (area > 0) {
    out.luminance = intensity / area;
    out.solid_angle = area / (r * r);
  }
  return out;
}

DirectGeometry compute_direct_geometry(const Receivers& receivers,
                                       const std::vector<Vec3>& ray_points,
                                       const RayTracer& occluders, Vec3 luminaire_position,
                                       const std::vector<Vec3>& opening_offsets, bool progress,
                                       const RankShares* ranks) {
  const std::size_t n = receivers.size();
  const RankShares own = ranks != nullptr ? *ranks : single_process_shares(n, kBlock);
  const std::vector<std::size_t> blocks = own.my_blocks();
  DirectGeometry g;
  g.dir_x.resize(n);
  g.dir_y.resize(n);
  g.dir_z.resize(n);
  g.factor.resize(n);
  std::atomic<std::uint64_t> rays{0};
  Progress bar("direct visibility", own.my_receivers(), progress);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size()), [&](const auto& range) {
    std::uint64_t local_rays = 0;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      for (std::size_t r = own.first(blocks[i]); r < own.last(blocks[i]); ++r) {
        const DirectFactor f = direct_factor(occluders, ray_points[r], receivers.normals[r],
                                             luminaire_position, opening_offsets, local_rays);
        g.dir_x[r] = static_cast<float>(f.direction.x);
        g.dir_y[r] = static_cast<float>(f.direction.y);
        g.dir_z[r] = static_cast<float>(f.direction.z);
        g.factor[r] = static_cast<float>(f.factor);
      }
      bar.advance(own.last(blocks[i]) - own.first(blocks[i]));
    }
    rays += local_rays;
  });
  bar.finish();
  g.rays = rays.load();
  // On several ranks each keeps its own rows: the bounce and the file need no more of them.
  if (!own.alone()) g.rays = sum_over_ranks(*own.exchange, g.rays);
  return g;
}

}  // namespace relight
