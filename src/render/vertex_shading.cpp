#include "render/vertex_shading.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "material/lambert.h"

namespace relight {

RaySample shade_ray(const VertexShadingInput& in, Vec3 origin, Vec3 dir) {
  return shade_hit(in, origin, dir, in.tracer.intersect({origin, dir}));
}

RaySample shade_hit(const VertexShadingInput& in, Vec3 origin, Vec3 dir, const RayHit& hit) {
  const auto vertex_rgb = [](std::span<const float> values, std::uint32_t v) {
    const std::size_t i = 3 * std::size_t{v};
    return Rgb{values[i], values[i + 1], values[i + 2]};
  };
  RaySample out;
  if (!hit.hit()) {
    if (in.background) {
      out.background = true;
      out.luminance = in.background(origin, dir);
    }
    return out;
  }
  const Triangle& t = in.triangles[hit.triangle];
  const Vec3 a = in.positions[t[0]], b = in.positions[t[1]], c = in.positions[t[2]];
  const Vec3 face = cross(b - a, c - a);
  if (dot(face, dir) >= 0) {  // back faces absorb: black
    out.back_side = true;
    return out;
  }
  const std::array<double, 3> bary{1 - hit.u - hit.v, hit.u, hit.v};
  Rgb e, albedo;
  for (std::size_t k = 0; k < 3; ++k) {
    e += vertex_rgb(in.irradiance, t[k]) * bary[k];
    albedo += vertex_rgb(in.vertex_albedo, t[k]) * bary[k];
  }
  // Per-vertex albedo is constant within a triangle (vertices split at material
  // boundaries), so ρ/π · E interpolates like per-vertex radiance.
  Rgb l;
  if (in.direct_at_hit) {
    const Vec3 p = a * bary[0] + b * bary[1] + c * bary[2], n = normalize(face);
    const std::optional<Rgb> glossy = in.glossy_radiance
                                          ? in.glossy_radiance(hit.triangle, bary, p, n, dir * -1.0)
                                          : std::nullopt;
    e += in.direct_at_hit(p, n);
    l = glossy ? *glossy : lambertian_radiance(albedo, e);
  } else if (!in.vertex_luminance.empty()) {
    for (std::size_t k = 0; k < 3; ++k) {
      const Rgb own = vertex_rgb(in.vertex_luminance, t[k]);
      l += (std::isnan(own.r) ? lambertian_radiance(vertex_rgb(in.vertex_albedo, t[k]),
                                                    vertex_rgb(in.irradiance, t[k]))
                              : own) *
           bary[k];
    }
  } else {
    l = lambertian_radiance(albedo, e);
  }
  out.surface = true;
  out.luminance = l;
  out.illuminance = e;
  return out;
}

namespace {

// Primary ray s (row-major in the pixel's samples_per_axis² strata) of pixel (x, y).
Vec3 primary_direction(const PinholeCamera& camera, int x, int y, int s, int samples_per_axis) {
  const int row = s / samples_per_axis, column = s % samples_per_axis;
  return camera.direction(x + (column + 0.5) / samples_per_axis,
                          y + (row + 0.5) / samples_per_axis);
}

}  // namespace

std::vector<RayHit> trace_primary(const PinholeCamera& camera, const RayTracer& tracer,
                                  int samples_per_axis) {
  const int w = camera.width, spp = samples_per_axis * samples_per_axis;
  std::vector<RayHit> hits(static_cast<std::size_t>(w) * camera.height * spp);
  tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const auto& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < w; ++x) {
        for (int s = 0; s < spp; ++s) {
          hits[(static_cast<std::size_t>(y) * w + x) * spp + s] =
              tracer.intersect({camera.eye, primary_direction(camera, x, y, s, samples_per_axis)});
        }
      }
    }
  });
  return hits;
}

std::vector<std::uint8_t> vertices_hit(std::span<const RayHit> hits,
                                       const std::vector<Triangle>& triangles,
                                       std::size_t vertex_count) {
  std::vector<std::uint8_t> seen(vertex_count, 0);
  for (const RayHit& hit : hits) {
    if (!hit.hit()) continue;
    for (const std::uint32_t v : triangles[hit.triangle]) seen[v] = 1;
  }
  return seen;
}

ShadedImages shade_vertices(const PinholeCamera& camera, const VertexShadingInput& in,
                            int samples_per_axis, std::span<const RayHit> hits) {
  const int w = camera.width, h = camera.height;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ShadedImages out{make_image(w, h), make_image(w, h)};
  const int spp = samples_per_axis * samples_per_axis;
  std::atomic<std::size_t> back_side_pixels{0};
  if (!hits.empty() && hits.size() != static_cast<std::size_t>(w) * h * spp) {
    throw std::invalid_argument("shade_vertices: hits of other rays");
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < w; ++x) {
        Rgb l_sum, e_sum;
        int covered = 0, escaped = 0, back_sides = 0;
        for (int s = 0; s < spp; ++s) {
          const Vec3 dir = primary_direction(camera, x, y, s, samples_per_axis);
          const RaySample sample =
              hits.empty() ? shade_ray(in, camera.eye, dir)
                           : shade_hit(in, camera.eye, dir,
                                       hits[(static_cast<std::size_t>(y) * w + x) * spp + s]);
          l_sum += sample.luminance;
          if (sample.background) ++escaped;
          if (sample.back_side) ++back_sides;
          if (!sample.surface) continue;
          e_sum += sample.illuminance;
          ++covered;
        }
        Rgb& lum = out.luminance.at(x, y);
        Rgb& ill = out.illuminance.at(x, y);
        lum = covered + escaped + back_sides == 0 ? Rgb{nan, nan, nan} : l_sum / spp;
        ill = covered == 0 ? Rgb{nan, nan, nan} : e_sum / covered;
        if (back_sides == spp) ++back_side_pixels;
      }
    }
  });
  out.back_side_pixels = back_side_pixels.load();
  return out;
}

}  // namespace relight
