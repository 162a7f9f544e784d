#include "sources/emitters/incident_radiance.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include "math/cubemap.h"
#include "math/sh.h"

namespace relight {

namespace {

struct SubRay {
  bool seen = false;
  std::uint32_t emitter = 0;
  double distance = 0;
};

SubRay trace(Vec3 x, Vec3 dir, const RayTracer& emitters, std::span<const Vec3> normals,
             const RayTracer* occluders) {
  const RayHit hit = emitters.intersect({x, dir});
  if (!hit.hit()) return {};
  if (!normals.empty() && dot(normals[hit.triangle], dir) >= 0) return {};  // its dark back
  if (occluders) {
    Ray shadow{x, dir};
    shadow.t_near = 1e-4;  // a sample at a receiver must not be shadowed by its own surface
    shadow.t_far = hit.t * (1 - 1e-6);
    if (occluders->occluded(shadow)) return {};
  }
  return {true, hit.triangle, hit.t};
}

// Direction through face position (s, t) ∈ [0, 1]² of texel-space face `face`.
Vec3 face_direction(int face, double s, double t) {
  return normalize(cubemap_direction({face, s, t}));
}

}  // namespace

IncidentRadiance sample_incident_radiance(Vec3 x, const RayTracer& emitters,
                                          std::span<const Rgb> emitter_radiance,
                                          std::span<const Vec3> emitter_normals,
                                          const RayTracer* occluders,
                                          const IncidentRadianceSettings& settings) {
  const int n = settings.face_size;
  if (n < 1 || settings.order < 1) {
    throw std::invalid_argument("incident radiance: face size and order must be >= 1");
  }
  const auto k = static_cast<std::size_t>(sh_count(settings.order));
  const std::vector<double>& texel_solid_angle = cubemap_solid_angles(n);  // one face, j·N + i
  IncidentRadiance out;
  out.sh.assign(k, Rgb{});
  std::vector<double> y(k);
  double inverse_distance_sum = 0, seen_weight = 0;
  const auto add = [&](const SubRay& s, Vec3 dir, double omega) {
    if (!s.seen) return;
    const Rgb l = emitter_radiance[s.emitter];
    sh_eval(settings.order, dir, y);
    for (std::size_t c = 0; c < k; ++c) out.sh[c] = out.sh[c] + l * (y[c] * omega);
    inverse_distance_sum += omega / s.distance;
    seen_weight += omega;
  };
  // Pass 1: 2×2 sub-rays in every texel.
  const std::size_t texels = cubemap_texel_count(n);
  std::vector<std::array<SubRay, 4>> coarse(texels);
  std::vector<std::array<Vec3, 4>> coarse_dir(texels);
  for (std::size_t index = 0; index < texels; ++index) {
    const CubemapTexel c = cubemap_texel_from_index(n, index);
    for (int q = 0; q < 4; ++q) {
      const double s = (c.i + 0.25 + 0.5 * (q % 2)) / n, t = (c.j + 0.25 + 0.5 * (q / 2)) / n;
      coarse_dir[index][static_cast<std::size_t>(q)] = face_direction(c.face, s, t);
      coarse[index][static_cast<std::size_t>(q)] = trace(
          x, coarse_dir[index][static_cast<std::size_t>(q)], emitters, emitter_normals, occluders);
    }
  }
  const auto same = [](const SubRay& a, const SubRay& b) {
    return a.seen == b.seen && (!a.seen || a.emitter == b.emitter);
  };
  // Pass 2: a texel whose sub-rays, and those of its 8 neighbours (across face edges too),
  // all agree keeps its 2×2; any other is integrated with 8×8 sub-rays. So an outline is
  // refined on both sides even where it misses the coarse rays of the texel it crosses.
  for (std::size_t index = 0; index < texels; ++index) {
    const CubemapTexel c = cubemap_texel_from_index(n, index);
    const double omega = texel_solid_angle[static_cast<std::size_t>(c.j * n + c.i)];
    const SubRay& first = coarse[index][0];
    bool uniform = true;
    for (int dj = -1; dj <= 1 && uniform; ++dj) {
      for (int di = -1; di <= 1 && uniform; ++di) {
        const Vec3 towards =
            cubemap_direction({c.face, (c.i + 0.5 + di) / n, (c.j + 0.5 + dj) / n});
        const std::size_t neighbour = cubemap_texel_index(n, cubemap_texel(n, towards));
        for (const SubRay& r : coarse[neighbour]) uniform = uniform && same(r, first);
      }
    }
    if (uniform) {
      for (std::size_t q = 0; q < 4; ++q) add(coarse[index][q], coarse_dir[index][q], omega / 4);
      continue;
    }
    constexpr int kFine = 8;
    for (int b = 0; b < kFine; ++b) {
      for (int a = 0; a < kFine; ++a) {
        const Vec3 dir =
            face_direction(c.face, (c.i + (a + 0.5) / kFine) / n, (c.j + (b + 0.5) / kFine) / n);
        add(trace(x, dir, emitters, emitter_normals, occluders), dir, omega / (kFine * kFine));
      }
    }
  }
  if (seen_weight > 0) out.harmonic_mean_distance = seen_weight / inverse_distance_sum;
  out.emitter_solid_angle = seen_weight;
  return out;
}

double sh_luminance_norm(std::span<const Rgb> sh) {
  double sum = 0;
  for (const Rgb& c : sh) sum += luminance(c) * luminance(c);
  return std::sqrt(sum);
}

}  // namespace relight
