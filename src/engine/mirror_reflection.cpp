#include "engine/mirror_reflection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

namespace {

// Receivers and lights closer to a plane than this see no image in it (m).
constexpr double kMinHeight = 1e-6;

}  // namespace

MirrorReflection::MirrorReflection(const RuntimeScene& scene,
                                   std::span<const std::int32_t> glossy_of,
                                   std::span<const MetallicRoughness> glossy)
    : scene_(&scene) {
  const std::vector<Triangle>& triangles = scene.opaque_triangles();
  const std::vector<std::uint32_t>& ids = scene.opaque_ids();
  planes_ = find_mirror_planes(scene.mesh_positions(), triangles, ids, [&](std::size_t i) {
    const std::uint32_t v = triangles[i][0];
    const std::int32_t g = v < glossy_of.size() ? glossy_of[v] : -1;
    return g >= 0 && reflects_as_mirror(glossy[static_cast<std::size_t>(g)]) ? std::int64_t{0}
                                                                             : std::int64_t{-1};
  });
  if (planes_.empty()) return;
  const std::uint32_t largest = *std::max_element(ids.begin(), ids.end());
  plane_of_ = mirror_plane_of(planes_, std::size_t{largest} + 1);
  vertex_.assign(scene.vertex_count(), 0);
  for (const MirrorPlane& plane : planes_) {
    for (const std::uint32_t id : plane.triangles) {
      for (const std::uint32_t v : scene.opaque_triangle(id)) vertex_[v] = 1;
    }
  }
}

Vec3 MirrorReflection::origin(std::size_t r) const {
  // Off the receiver's own surface, as every ray leaving a receiver starts
  // (engine/receivers.h receiver_ray_points).
  return offset_from_surface(scene_->ray_point(r), scene_->normal(r));
}

bool MirrorReflection::reaches_plane(std::size_t r, std::size_t p, Vec3 w, double span,
                                     MirrorPath& out) const {
  const Vec3 x = origin(r);
  const RayHit hit = scene_->occluders().intersect({x, w, 0, span});
  if (!hit.hit() || plane_of_[hit.triangle] != static_cast<std::int32_t>(p)) return false;
  const Vec3 y = x + w * hit.t;
  // The mirror's vertex nearest y: the corner of largest barycentric weight.
  const Triangle& t = scene_->opaque_triangle(hit.triangle);
  const double weights[3] = {1 - hit.u - hit.v, hit.u, hit.v};
  const auto corner = static_cast<std::size_t>(
      std::max_element(std::begin(weights), std::end(weights)) - std::begin(weights));
  out.receiver = static_cast<std::uint32_t>(r);
  out.vertex = t[corner];
  out.at[0] = static_cast<float>(y.x);
  out.at[1] = static_cast<float>(y.y);
  out.at[2] = static_cast<float>(y.z);
  return true;
}

namespace {

// Per receiver its paths (from `paths_of(r, out)`), concatenated in receiver order.
template <typename PathsOf>
std::vector<MirrorPath> receiver_by_receiver(std::size_t receivers, const PathsOf& paths_of) {
  std::vector<std::vector<MirrorPath>> per_receiver(receivers);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, receivers, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) paths_of(r, per_receiver[r]);
  });
  std::vector<MirrorPath> out;
  for (const std::vector<MirrorPath>& paths : per_receiver) {
    out.insert(out.end(), paths.begin(), paths.end());
  }
  return out;
}

}  // namespace

std::vector<MirrorPath> MirrorReflection::trace(Vec3 light) const {
  return receiver_by_receiver(
      scene_->receivers(), [&](std::size_t r, std::vector<MirrorPath>& out) {
        const Vec3 x = origin(r), n = scene_->normal(r);
        for (std::size_t p = 0; p < planes_.size(); ++p) {
          const MirrorPlane& plane = planes_[p];
          if (plane.height(x) <= kMinHeight || plane.height(light) <= kMinHeight) continue;
          const Vec3 unfolded = plane.image(light) - x;
          const double d = length(unfolded);
          const Vec3 w = unfolded / d;
          const double cos_x = dot(n, w);
          MirrorPath path;
          if (cos_x <= 0 || !reaches_plane(r, p, w, d, path)) continue;
          const Vec3 y{path.at[0], path.at[1], path.at[2]};
          const Vec3 to_light = light - y;
          const double span = length(to_light);
          const double cos_y = dot(plane.normal, to_light) / span;
          if (cos_y <= 0) continue;
          const Vec3 start = offset_from_surface(y, plane.normal);
          const Vec3 toward = light - start;
          const double gap = length(toward);
          if (scene_->occluders().occluded({start, toward / gap, 0, gap * (1 - 1e-6)})) continue;
          const Vec3 emit = (y - light) / span;
          path.emit[0] = static_cast<float>(emit.x);
          path.emit[1] = static_cast<float>(emit.y);
          path.emit[2] = static_cast<float>(emit.z);
          path.factor = static_cast<float>(cos_x / (d * d));
          path.cos_in = static_cast<float>(cos_y);
          out.push_back(path);
        }
      });
}

std::vector<MirrorPath> MirrorReflection::trace_parallel(Vec3 toward) const {
  return receiver_by_receiver(scene_->receivers(), [&](std::size_t r,
                                                       std::vector<MirrorPath>& out) {
    const Vec3 x = origin(r), n = scene_->normal(r);
    for (std::size_t p = 0; p < planes_.size(); ++p) {
      const MirrorPlane& plane = planes_[p];
      const double cos_y = dot(plane.normal, toward);
      if (cos_y <= 0 || plane.height(x) <= kMinHeight) continue;
      // The light's image lies along the mirrored direction, below the plane.
      const Vec3 w = toward - plane.normal * (2 * cos_y);
      const double cos_x = dot(n, w);
      MirrorPath path;
      if (cos_x <= 0 || !reaches_plane(r, p, w, std::numeric_limits<double>::infinity(), path)) {
        continue;
      }
      path.emit[0] = static_cast<float>(-toward.x);
      path.emit[1] = static_cast<float>(-toward.y);
      path.emit[2] = static_cast<float>(-toward.z);
      path.factor = static_cast<float>(cos_x);
      path.cos_in = static_cast<float>(cos_y);
      out.push_back(path);
    }
  });
}

}  // namespace relight
