// Vertex normals and vertex splitting, the last preparation step. A receiver vertex carries
// one normal and one material, so the triangles around a welded vertex are grouped: two
// triangles that share an edge at the vertex (with matching orientation) join the same group
// when they have the same material and their normals differ by at most the crease angle;
// every group becomes its own output vertex. The group normal is the angle-weighted mean of
// its face normals (Thürmer and Wüthrich 1998): unlike area weights it does not change when
// subdivision splits the faces, so an original vertex keeps its normal at any max_edge.
// A chain of gentle edges can still gather faces that bend far apart (a cone tip); a face
// whose normal ends up too far from its group's (not clearly on its front side) is split off
// until every face agrees, so shading normals never point behind their triangle.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

// A face stays in its group only if the group normal is within about 89.4 degrees of it.
constexpr double kMinFrontCosine = 0.01;

struct Corner {
  std::uint32_t triangle = 0;
  std::uint32_t next = 0, previous = 0;  // the other two vertices, in winding order
};

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// Angle at p between the edges to q and r, robust for tiny and obtuse angles.
double corner_angle(Vec3 p, Vec3 q, Vec3 r) {
  const Vec3 u = q - p, w = r - p;
  return std::atan2(length(cross(u, w)), dot(u, w));
}

}  // namespace

PreparedMesh split_and_shade(const IndexedMesh& mesh, double crease_deg) {
  const std::size_t vertex_count = mesh.positions.size();
  const std::size_t triangle_count = mesh.triangles.size();
  const double crease_cosine = std::cos(radians(std::clamp(crease_deg, 0.0, 180.0)));

  std::vector<Vec3> face_normal(triangle_count);
  std::vector<std::array<double, 3>> angle(triangle_count);
  for (std::size_t t = 0; t < triangle_count; ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    face_normal[t] = normalize(cross(b - a, c - a));
    angle[t] = {corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)};
  }

  // Corners grouped by vertex (counting sort keeps triangle order within a vertex).
  std::vector<std::uint32_t> first(vertex_count + 1, 0);
  for (const Triangle& tri : mesh.triangles) {
    for (const std::uint32_t v : tri) ++first[v + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> corner_of(3 * triangle_count);  // corner id = 3 t + k
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < triangle_count; ++t) {
      for (int k = 0; k < 3; ++k) {
        corner_of[fill[mesh.triangles[t][k]]++] = static_cast<std::uint32_t>(3 * t + k);
      }
    }
  }

  PreparedMesh out;
  out.triangles = mesh.triangles;
  out.triangle_material = mesh.triangle_material;
  out.positions.reserve(vertex_count);
  out.normals.reserve(vertex_count);
  out.vertex_material.reserve(vertex_count);

  std::vector<Corner> corners;
  std::vector<std::uint32_t> parent, group_of, order;
  std::vector<Vec3> group_sum;
  std::vector<std::uint32_t> slot;
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const std::uint32_t begin = first[v], end = first[v + 1];
    const std::uint32_t n = end - begin;
    if (n == 0) continue;
    corners.clear();
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t id = corner_of[i];
      const Triangle& tri = mesh.triangles[id / 3];
      const int k = static_cast<int>(id % 3);
      corners.push_back({id / 3, tri[(k + 1) % 3], tri[(k + 2) % 3]});
    }

    // Join corners across smooth edges. The edge v->w of one triangle meets w->v of its
    // neighbour (consistent orientation); sorting by `next` finds partners in O(n log n).
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0u);
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t i, std::uint32_t j) { return corners[i].next < corners[j].next; });
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t w = corners[j].previous;
      auto it = std::lower_bound(
          order.begin(), order.end(), w,
          [&](std::uint32_t i, std::uint32_t value) { return corners[i].next < value; });
      for (; it != order.end() && corners[*it].next == w; ++it) {
        const std::uint32_t i = *it;
        const std::uint32_t ti = corners[i].triangle, tj = corners[j].triangle;
        if (mesh.triangle_material[ti] != mesh.triangle_material[tj]) continue;
        if (dot(face_normal[ti], face_normal[tj]) < crease_cosine) continue;
        parent[find(parent, i)] = find(parent, j);
      }
    }

    // Groups in order of their first corner; then split off faces the mean leaves behind.
    group_of.assign(n, 0);
    std::uint32_t groups = 0;
    slot.assign(n, UINT32_MAX);
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t root = find(parent, i);
      if (slot[root] == UINT32_MAX) slot[root] = groups++;
      group_of[i] = slot[root];
    }
    bool settled = false;
    while (!settled) {
      group_sum.assign(groups, Vec3{});
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t t = corners[i].triangle;
        group_sum[group_of[i]] += face_normal[t] * angle[t][corner_of[begin + i] % 3];
      }
      settled = true;
      for (std::uint32_t i = 0; i < n; ++i) {
        const Vec3 sum = group_sum[group_of[i]];
        const double sum_length = length(sum);
        const bool front = sum_length > 0 && dot(sum, face_normal[corners[i].triangle]) >
                                                 kMinFrontCosine * sum_length;
        if (!front) {
          group_of[i] = groups++;  // on its own it is exactly on its front side
          settled = false;
        }
      }
    }

    // Output one vertex per non-empty group, in order of the group's first corner.
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    slot.assign(groups, UINT32_MAX);
    std::uint32_t used = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t g = group_of[i];
      if (slot[g] == UINT32_MAX) {
        slot[g] = used++;
        out.positions.push_back(mesh.positions[v]);
        out.normals.push_back(normalize(group_sum[g]));
        out.vertex_material.push_back(mesh.triangle_material[corners[i].triangle]);
      }
      const std::uint32_t id = corner_of[begin + i];
      out.triangles[id / 3][id % 3] = base + slot[g];
    }
  }
  return out;
}

}  // namespace relight
