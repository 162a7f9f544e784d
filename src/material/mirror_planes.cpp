#include "material/mirror_planes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace relight {

namespace {

// Planes agree when their normals and offsets agree within this (unit normal, metres).
constexpr double kPlaneTolerance = 1e-4;

std::int64_t quantise(double x) {
  return std::llround(x / kPlaneTolerance);
}

}  // namespace

std::vector<MirrorPlane> find_mirror_planes(
    const std::vector<Vec3>& positions, std::span<const Triangle> triangles,
    std::span<const std::uint32_t> ids, const std::function<std::int64_t(std::size_t)>& group_of) {
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t, std::int64_t>;
  std::map<Key, std::size_t> index;
  std::vector<MirrorPlane> planes;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const std::int64_t group = group_of(i);
    if (group < 0) continue;
    const Vec3 a = positions[triangles[i][0]], b = positions[triangles[i][1]],
               c = positions[triangles[i][2]];
    const Vec3 face = cross(b - a, c - a);
    const double twice_area = length(face);
    if (!(twice_area > 0)) continue;
    const Vec3 n = face / twice_area;
    const double offset = dot(n, a);
    const Key key{group, quantise(n.x), quantise(n.y), quantise(n.z), quantise(offset)};
    auto [it, added] = index.try_emplace(key, planes.size());
    if (added) planes.push_back({n, offset, 0, group, {}});
    MirrorPlane& plane = planes[it->second];
    plane.area += twice_area / 2;
    plane.triangles.push_back(ids[i]);
  }
  if (planes.size() > kMaxMirrorPlanes) {
    std::stable_sort(planes.begin(), planes.end(),
                     [](const MirrorPlane& a, const MirrorPlane& b) { return a.area > b.area; });
    planes.resize(kMaxMirrorPlanes);
  }
  for (MirrorPlane& plane : planes) std::sort(plane.triangles.begin(), plane.triangles.end());
  std::sort(planes.begin(), planes.end(), [](const MirrorPlane& a, const MirrorPlane& b) {
    return a.triangles.front() < b.triangles.front();
  });
  return planes;
}

std::vector<std::int32_t> mirror_plane_of(std::span<const MirrorPlane> planes,
                                          std::size_t id_count) {
  std::vector<std::int32_t> out(id_count, -1);
  for (std::size_t p = 0; p < planes.size(); ++p) {
    for (const std::uint32_t id : planes[p].triangles) {
      if (id < id_count) out[id] = static_cast<std::int32_t>(p);
    }
  }
  return out;
}

}  // namespace relight
