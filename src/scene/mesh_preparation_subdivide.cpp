// Subdivision to a maximum edge length, so that per-vertex transfer samples lighting densely
// enough. Each triangle's longest edge is bisected until no edge exceeds max_edge. The split
// rule depends on the edge alone (split iff longer than max_edge, at its midpoint, looked up
// in an edge -> midpoint map shared by all triangles), so the two triangles on an edge cut it
// at the same points and the result has no T-junctions. Longest-edge bisection keeps angles
// bounded away from zero and every new edge is at most sqrt(3)/2 of the edge it replaces, so
// it terminates. Children keep the parent's winding and lie in its plane.
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

#include "common/input_error.h"
#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

struct SplitHash {
  std::size_t operator()(std::uint64_t k) const {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
  }
};

}  // namespace

void subdivide_long_edges(IndexedMesh& mesh, double max_edge) {
  if (!(max_edge > 0)) return;
  const double max2 = max_edge * max_edge;

  // No triangle with edges <= max_edge is larger than the equilateral one, so this lower
  // bound on the result's size rejects a hopeless max_edge before any work is done.
  double at_least = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    at_least += 0.5 * length(cross(b - a, c - a)) / (std::sqrt(3.0) / 4 * max2);
  }
  if (at_least > static_cast<double>(kMaxPreparedTriangles)) {
    fail_input("mesh preparation", "max_edge " + std::to_string(max_edge) +
                                       " m would create more than " +
                                       std::to_string(kMaxPreparedTriangles) + " triangles");
  }
  std::vector<Vec3>& positions = mesh.positions;
  std::unordered_map<std::uint64_t, std::uint32_t, SplitHash> midpoint;

  const auto split = [&](std::uint32_t a, std::uint32_t b) {
    const auto [it, inserted] =
        midpoint.try_emplace(edge_key(a, b), static_cast<std::uint32_t>(positions.size()));
    if (inserted) {
      if (positions.size() >= UINT32_MAX) {
        fail_input("mesh preparation", "subdivision needs more than 2^32 vertices");
      }
      // Symmetric in a and b, so both triangles on the edge compute the same point.
      positions.push_back((positions[a] + positions[b]) * 0.5);
    }
    return it->second;
  };

  std::vector<Triangle> out_triangles;
  std::vector<std::uint32_t> out_material, out_source;
  out_triangles.reserve(mesh.triangles.size());
  out_material.reserve(mesh.triangles.size());
  out_source.reserve(mesh.triangles.size());
  std::vector<Triangle> stack;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const std::uint32_t material = mesh.triangle_material[i];
    stack.push_back(mesh.triangles[i]);
    while (!stack.empty()) {
      const Triangle t = stack.back();
      stack.pop_back();
      // Edge k runs from t[k] to t[k+1]. dot(d, d) is the same whichever way d points.
      double longest = 0;
      int edge = -1;
      for (int k = 0; k < 3; ++k) {
        const Vec3 d = positions[t[(k + 1) % 3]] - positions[t[k]];
        const double length2 = dot(d, d);
        if (length2 > max2 && length2 > longest) {
          longest = length2;
          edge = k;
        }
      }
      if (edge < 0) {
        out_triangles.push_back(t);
        out_material.push_back(material);
        out_source.push_back(mesh.triangle_source[i]);
        if (out_triangles.size() > kMaxPreparedTriangles) {
          fail_input("mesh preparation", "max_edge " + std::to_string(max_edge) +
                                             " m would create more than " +
                                             std::to_string(kMaxPreparedTriangles) + " triangles");
        }
        continue;
      }
      const std::uint32_t a = t[edge], b = t[(edge + 1) % 3], c = t[(edge + 2) % 3];
      const std::uint32_t m = split(a, b);
      // (a, b, c) -> (a, m, c) + (m, b, c): same winding, same plane.
      stack.push_back({m, b, c});
      stack.push_back({a, m, c});
    }
  }
  mesh.triangles = std::move(out_triangles);
  mesh.triangle_material = std::move(out_material);
  mesh.triangle_source = std::move(out_source);
}

}  // namespace relight
