// Analytic scene primitives tessellated to triangles (docs/scene-format.md):
// quad (normal = normalize(u × v)), axis-aligned box and sphere with inward or outward
// normals. Orientation matters: surfaces reflect on their front side only.
#pragma once

#include <cstdint>

#include "scene/triangle_soup.h"

namespace relight {

enum class Facing { kOutward, kInward };

TriangleSoup make_quad(Vec3 corner, Vec3 u, Vec3 v, std::uint32_t material);
TriangleSoup make_box(Vec3 lo, Vec3 hi, Facing facing, std::uint32_t material);
// Geodesic sphere: an icosahedron subdivided `subdivisions` times (20·4^s triangles),
// vertices on the sphere.
TriangleSoup make_sphere(Vec3 center, double radius, Facing facing, int subdivisions,
                         std::uint32_t material);

}  // namespace relight
