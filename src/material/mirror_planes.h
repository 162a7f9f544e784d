// Near-mirror planes (the mirror limit): flat glossy surfaces so smooth that their
// reflection of a point light is an image of it. A metal floor of roughness 0.05 (GGX α =
// 0.0025) reflects a downlight into a cone of about a degree: the gather operator's entries,
// one BRDF value per vertex a few degrees apart as a ceiling receiver sees them, cannot
// resolve that (engine/glossy_first_bounce.h), and a backward path tracer almost never finds
// the light through it (reference/reference_mirror.h). The image-source method can: the light at
// p, mirrored in the plane, is a second light at p' whose rays reach a receiver x through the
// point y where the segment x–p' crosses the plane (Allen and Berkley 1979, "Image method for
// efficiently simulating small-room acoustics", §II; the geometric optics of a plane mirror).
//
// Which surfaces: triangles of a glTF metallic–roughness material of roughness ≤
// kMirrorRoughness (α ≤ 0.0225: a reflected cone of ±2.6°, which blurs the image of a light
// by ±10 cm at 2 m — below the size of a downlight's pool) grouped into planes (normal and
// offset within 1e-4), at most kMaxMirrorPlanes of them, the largest by area. A curved
// near-mirror (a tessellated sphere) would give a plane per triangle; beyond the cap its
// triangles reflect through the gather operator as rougher surfaces do. Pinned by
// tests/engine/mirror_planes_test.cpp and tests/cli/mirror_limit_test.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "material/metallic_roughness.h"
#include "math/vec3.h"
#include "scene/triangle.h"

namespace relight {

inline constexpr double kMirrorRoughness = 0.15;
inline constexpr std::size_t kMaxMirrorPlanes = 16;

inline bool reflects_as_mirror(const MetallicRoughness& m) {
  return m.roughness <= kMirrorRoughness;
}

struct MirrorPlane {
  Vec3 normal;                           // unit, toward the triangles' front
  double offset = 0;                     // normal · x for x in the plane
  double area = 0;                       // m², of its triangles
  std::int64_t group = 0;                // the caller's key its triangles share
  std::vector<std::uint32_t> triangles;  // the caller's ids, ascending

  // Signed distance of p in front of the plane.
  double height(Vec3 p) const { return dot(normal, p) - offset; }
  // p mirrored in the plane.
  Vec3 image(Vec3 p) const { return p - normal * (2 * height(p)); }
};

// The near-mirror planes of `triangles` (indices into `positions`; ids[i] names triangle i):
// group_of(i) is the key of triangle i (its material, say), or −1 when it is no mirror;
// triangles of one key in one plane form a plane. The kMaxMirrorPlanes largest, in the order
// of their first triangle. Degenerate triangles are skipped.
std::vector<MirrorPlane> find_mirror_planes(
    const std::vector<Vec3>& positions, std::span<const Triangle> triangles,
    std::span<const std::uint32_t> ids, const std::function<std::int64_t(std::size_t)>& group_of);

// Per id (0 … id_count − 1): the index of the plane holding it, or −1.
std::vector<std::int32_t> mirror_plane_of(std::span<const MirrorPlane> planes,
                                          std::size_t id_count);

}  // namespace relight
