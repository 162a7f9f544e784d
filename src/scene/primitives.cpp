#include "scene/primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace relight {

namespace {

void flip_all(TriangleSoup& soup) {
  for (Triangle& t : soup.triangles) std::swap(t[1], t[2]);
}

}  // namespace

TriangleSoup make_quad(Vec3 corner, Vec3 u, Vec3 v, std::uint32_t material) {
  TriangleSoup q;
  q.positions = {corner, corner + u, corner + u + v, corner + v};
  q.triangles = {{0, 1, 2}, {0, 2, 3}};
  q.triangle_material = {material, material};
  return q;
}

TriangleSoup make_box(Vec3 lo, Vec3 hi, Facing facing, std::uint32_t material) {
  const Vec3 d = hi - lo;
  const Vec3 ex{d.x, 0, 0}, ey{0, d.y, 0}, ez{0, 0, d.z};
  TriangleSoup box;
  // Each face as corner + u + v with u × v pointing out of the box.
  box.append(make_quad(lo, ex, ez, material));       // y = lo.y, normal -y
  box.append(make_quad(lo + ey, ez, ex, material));  // y = hi.y, normal +y
  box.append(make_quad(lo, ez, ey, material));       // x = lo.x, normal -x
  box.append(make_quad(lo + ex, ey, ez, material));  // x = hi.x, normal +x
  box.append(make_quad(lo, ey, ex, material));       // z = lo.z, normal -z
  box.append(make_quad(lo + ez, ex, ey, material));  // z = hi.z, normal +z
  if (facing == Facing::kInward) flip_all(box);
  return box;
}

TriangleSoup make_sphere(Vec3 center, double radius, Facing facing, int subdivisions,
                         std::uint32_t material) {
  // Icosahedron: the 12 vertices (0, ±1, ±φ) and cyclic permutations, 20 outward faces.
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0},
                            {0, -1, p}, {0, 1, p}, {0, -1, -p}, {0, 1, -p},
                            {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& v : unit) v = normalize(v);
  std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      unit.push_back(normalize(unit[a] + unit[b]));
      const auto index = static_cast<std::uint32_t>(unit.size() - 1);
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(faces.size() * 4);
    for (const Triangle& f : faces) {
      const std::uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  TriangleSoup sphere;
  sphere.positions.reserve(unit.size());
  for (const Vec3& u : unit) sphere.positions.push_back(center + u * radius);
  sphere.triangles = std::move(faces);
  sphere.triangle_material.assign(sphere.triangles.size(), material);
  if (facing == Facing::kInward) flip_all(sphere);
  return sphere;
}

}  // namespace relight
