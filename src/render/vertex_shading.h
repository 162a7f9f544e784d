// Images from per-vertex results (Dobashi et al. 1995's display step, Eq. 18 then
// Gouraud shading): a primary ray per sub-pixel finds the visible triangle, and the
// vertex values are interpolated with the hit's barycentrics — the same interpolation the
// gather operator assumes, so an image shows exactly what the transfer computed.
// Luminance of a vertex is albedo/π · E (diffuse), or its own luminance toward the eye where
// given (glossy vertices); back faces show black.
#pragma once

#include <array>
#include <cstdint>

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "image/image.h"
#include "scene/camera.h"
#include "scene/triangle_soup.h"
#include "trace/ray_tracer.h"

namespace relight {

struct VertexShadingInput {
  const RayTracer& tracer;             // ids are indices into `triangles`
  const std::vector<Vec3>& positions;  // per vertex
  const std::vector<Triangle>& triangles;
  std::span<const float> vertex_albedo;  // 3 per vertex
  std::span<const float> irradiance;     // 3 per vertex (lux), at least 3·vertices
  // When set, irradiance holds interreflected light only and this gives the direct
  // irradiance at each hit point and its geometric normal (runtime/direct_light.h).
  std::function<Rgb(Vec3 point, Vec3 normal)> direct_at_hit;
  // When set, a ray that meets no surface shows this luminance (the view out of a window:
  // the portal's shell); its illuminance stays NaN.
  std::function<Rgb(Vec3 origin, Vec3 dir)> background;
  // With direct_at_hit, when set: the luminance a glossy surface sends toward the eye
  // (render/glossy_pixels.h) at a hit on `triangle` (at barycentrics `bary` of its three vertices)
  // seen from direction v (unit, toward the eye) — the pixel's luminance instead of ρ/π E — or
  // nothing for a Lambertian triangle.
  std::function<std::optional<Rgb>(std::uint32_t triangle, const std::array<double, 3>& bary,
                                   Vec3 point, Vec3 normal, Vec3 v)>
      glossy_radiance;
  // Without direct_at_hit, when set (3 per vertex): the luminance each vertex sends toward the eye,
  // interpolated instead of ρ/π E where it is not NaN (glossy vertices).
  std::span<const float> vertex_luminance;
};

// What one ray of shade_vertices sees from `origin` along `dir`: a front surface (its
// luminance and illuminance), the background (luminance only), or nothing (a back face, or no
// hit without a background).
struct RaySample {
  bool surface = false, background = false;
  bool back_side = false;  // the back of a surface: it absorbs, and shows black
  Rgb luminance, illuminance;
};
RaySample shade_ray(const VertexShadingInput& input, Vec3 origin, Vec3 dir);
// The same for a ray whose hit in input.tracer is already known.
RaySample shade_hit(const VertexShadingInput& input, Vec3 origin, Vec3 dir, const RayHit& hit);

struct ShadedImages {
  Image luminance;    // cd/m² per channel; black where only the back of surfaces is seen, NaN
                      // where nothing is (no surface, no background)
  Image illuminance;  // lux per channel; NaN where no front surface is seen
  std::size_t back_side_pixels = 0;  // pixels every sample of which met the back of a surface
};

// `samples_per_axis`² stratified primary rays per pixel. With `hits` (trace_primary's of the
// same camera, tracer and samples) the rays are not traced again.
ShadedImages shade_vertices(const PinholeCamera& camera, const VertexShadingInput& input,
                            int samples_per_axis = 2, std::span<const RayHit> hits = {});

// The hits of shade_vertices' primary rays in `tracer`, pixel by pixel (rows from the top),
// sample by sample within a pixel.
std::vector<RayHit> trace_primary(const PinholeCamera& camera, const RayTracer& tracer,
                                  int samples_per_axis = 2);

// 1 for each vertex of a triangle that one of `hits` meets: the only vertices an image of those
// rays interpolates, so the only ones whose view-dependent shading it needs (Iwasaki et al.,
// Cyberworlds, §V.B, the capture paper: "calculates only the radiances of visible vertices",
// found there from a buffer of triangle IDs).
std::vector<std::uint8_t> vertices_hit(std::span<const RayHit> hits,
                                       const std::vector<Triangle>& triangles,
                                       std::size_t vertex_count);

}  // namespace relight
