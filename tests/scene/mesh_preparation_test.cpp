// Mesh preparation (scene/mesh_preparation.h): welding, degenerate removal, conforming
// subdivision, crease- and material-aware vertex normals.
#include "scene/mesh_preparation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/input_error.h"
#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

// Adds one triangle with its own three soup vertices (no sharing).
void add_separate(TriangleSoup& soup, Vec3 a, Vec3 b, Vec3 c, std::uint32_t material = 0) {
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), {a, b, c});
  soup.triangles.push_back({base, base + 1, base + 2});
  soup.triangle_material.push_back(material);
}

// Unit cube [0,1]^3 as 12 separate outward-facing triangles (36 soup vertices).
TriangleSoup cube_soup() {
  TriangleSoup soup;
  const auto corner = [](int i) {
    return Vec3{double(i & 1), double((i >> 1) & 1), double(i >> 2)};
  };
  // Quads as corner ids, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    add_separate(soup, corner(q[0]), corner(q[1]), corner(q[2]));
    add_separate(soup, corner(q[0]), corner(q[2]), corner(q[3]));
  }
  return soup;
}

// UV sphere of radius r around the origin, as separate triangles (so welding is needed).
TriangleSoup sphere_soup(double r, int slices, int stacks) {
  TriangleSoup soup;
  const auto point = [&](int i, int j) {
    const double theta = kPi * j / stacks, phi = 2 * kPi * (i % slices) / slices;
    return Vec3{r * std::sin(theta) * std::cos(phi), r * std::cos(theta),
                -r * std::sin(theta) * std::sin(phi)};
  };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const Vec3 a = point(i, j), b = point(i, j + 1), c = point(i + 1, j + 1), d = point(i + 1, j);
      if (j > 0) add_separate(soup, a, b, d);
      if (j + 1 < stacks) add_separate(soup, d, b, c);
    }
  }
  return soup;
}

Vec3 geometric_normal(const std::vector<Vec3>& p, const Triangle& t) {
  return normalize(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]));
}

double area(const std::vector<Vec3>& p, const Triangle& t) {
  return 0.5 * length(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]));
}

// Checks the invariants every prepared mesh has.
void expect_well_formed(const PreparedMesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  ASSERT_EQ(mesh.vertex_material.size(), mesh.positions.size());
  ASSERT_EQ(mesh.triangle_material.size(), mesh.triangles.size());
  for (const Vec3& n : mesh.normals) EXPECT_NEAR(length(n), 1.0, 1e-12);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 g = geometric_normal(mesh.positions, mesh.triangles[t]);
    for (const std::uint32_t v : mesh.triangles[t]) {
      ASSERT_LT(v, mesh.positions.size());
      EXPECT_GT(dot(mesh.normals[v], g), 0.0) << "triangle " << t;
      EXPECT_EQ(mesh.vertex_material[v], mesh.triangle_material[t]);
    }
  }
}

using PositionKey = std::tuple<double, double, double>;
PositionKey key(Vec3 p) {
  return {p.x, p.y, p.z};
}

// Undirected edges by their end positions -> number of triangles using them.
std::map<std::pair<PositionKey, PositionKey>, int> edge_use(const PreparedMesh& mesh) {
  std::map<std::pair<PositionKey, PositionKey>, int> use;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      PositionKey a = key(mesh.positions[t[k]]), b = key(mesh.positions[t[(k + 1) % 3]]);
      if (b < a) std::swap(a, b);
      ++use[{a, b}];
    }
  }
  return use;
}

TEST(MeshPreparation, WeldMergesCubeSoupToEightPositions) {
  const TriangleSoup soup = cube_soup();
  ASSERT_EQ(soup.positions.size(), 36u);
  const WeldResult welded = weld_positions(soup.positions, 1e-6);
  EXPECT_EQ(welded.positions.size(), 8u);
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    EXPECT_EQ(welded.positions[welded.remap[i]], soup.positions[i]);
  }
}

TEST(MeshPreparation, WeldFindsNeighboursAcrossGridCellBorders) {
  // 0 is a cell border for any cell size; 6e-7 apart is within epsilon = 1e-6.
  const std::vector<Vec3> points = {{-3e-7, 5, 5},         {3e-7, 5, 5},      {5, -3e-7, 5},
                                    {5, 3e-7, 5},          {5, 5, -3e-7},     {5, 5, 3e-7},
                                    {-2e-7, -2e-7, -2e-7}, {2e-7, 2e-7, 2e-7}};
  const WeldResult welded = weld_positions(points, 1e-6);
  EXPECT_EQ(welded.positions.size(), 4u);
  EXPECT_EQ(welded.remap[0], welded.remap[1]);
  EXPECT_EQ(welded.remap[2], welded.remap[3]);
  EXPECT_EQ(welded.remap[4], welded.remap[5]);
  EXPECT_EQ(welded.remap[6], welded.remap[7]);
}

TEST(MeshPreparation, WeldKeepsPositionsFartherThanEpsilonApart) {
  const std::vector<Vec3> points = {{0, 0, 0}, {2e-6, 0, 0}, {0, 1.5e-6, 0}, {0, 0, 0}};
  const WeldResult welded = weld_positions(points, 1e-6);
  EXPECT_EQ(welded.positions.size(), 3u);
  EXPECT_EQ(welded.remap[3], welded.remap[0]);
  // epsilon 0: only identical positions merge (-0 equals +0).
  const std::vector<Vec3> exact = {{0, 0, 0}, {-0.0, 0, 0}, {1e-300, 0, 0}};
  EXPECT_EQ(weld_positions(exact, 0).positions.size(), 2u);
}

TEST(MeshPreparation, CubeWithCreaseGivesTwentyFourAxisAlignedVertices) {
  const PreparedMesh mesh = prepare_mesh(cube_soup(), {.max_edge = 0, .crease_deg = 30});
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.positions.size(), 24u);
  std::set<PositionKey> distinct;
  for (const Vec3& p : mesh.positions) distinct.insert(key(p));
  EXPECT_EQ(distinct.size(), 8u);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 g = geometric_normal(mesh.positions, mesh.triangles[t]);
    for (const std::uint32_t v : mesh.triangles[t]) {
      EXPECT_NEAR(dot(mesh.normals[v], g), 1.0, 1e-12);
      EXPECT_NEAR(
          std::abs(mesh.normals[v].x) + std::abs(mesh.normals[v].y) + std::abs(mesh.normals[v].z),
          1.0, 1e-12);
    }
  }
}

TEST(MeshPreparation, CubeBelowCreaseAngleIsSmoothedAtCorners) {
  const PreparedMesh mesh = prepare_mesh(cube_soup(), {.max_edge = 0, .crease_deg = 100});
  expect_well_formed(mesh);
  ASSERT_EQ(mesh.positions.size(), 8u);
  for (std::size_t v = 0; v < 8; ++v) {
    const Vec3 outward = normalize(mesh.positions[v] - Vec3{0.5, 0.5, 0.5});
    EXPECT_NEAR(dot(mesh.normals[v], outward), 1.0, 1e-12);
  }
}

TEST(MeshPreparation, SmoothSphereHasOneRadialNormalPerPosition) {
  const TriangleSoup soup = sphere_soup(2.0, 48, 24);
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = 0, .crease_deg = 30});
  expect_well_formed(mesh);
  EXPECT_EQ(mesh.positions.size(), std::size_t{48 * 23 + 2});
  std::set<PositionKey> distinct;
  for (const Vec3& p : mesh.positions) distinct.insert(key(p));
  EXPECT_EQ(distinct.size(), mesh.positions.size());
  double worst_deg = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const double c = dot(mesh.normals[v], normalize(mesh.positions[v]));
    worst_deg = std::max(worst_deg, degrees(std::acos(std::min(1.0, c))));
  }
  EXPECT_LT(worst_deg, 2.0);
}

TEST(MeshPreparation, MaterialBoundaryDuplicatesVerticesOnSharedEdge) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  soup.triangle_material = {3, 5};
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = 0});
  expect_well_formed(mesh);
  ASSERT_EQ(mesh.positions.size(), 6u);
  int on_shared_edge = 0;
  for (const Vec3& p : mesh.positions) on_shared_edge += (p == Vec3{0, 0, 0} || p == Vec3{1, 1, 0});
  EXPECT_EQ(on_shared_edge, 4);  // both ends of the diagonal, once per material
  for (const Vec3& n : mesh.normals) EXPECT_NEAR(n.z, 1.0, 1e-15);
  EXPECT_EQ(mesh.triangle_material, (std::vector<std::uint32_t>{3, 5}));
}

TEST(MeshPreparation, DegenerateTrianglesAreDropped) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1e-9, 0, 0}};
  soup.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 0, 2}, {0, 4, 2}};
  soup.triangle_material = {0, 1, 2, 3};
  // (0,1,3) is collinear; (0,0,2) repeats a vertex; (0,4,2) collapses when 4 welds onto 0.
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = 0, .weld_epsilon = 1e-6});
  expect_well_formed(mesh);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangle_material[0], 0u);
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(MeshPreparation, SubdivisionBoundsEdgesPreservesAreaAndConforms) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  soup.triangle_material = {0, 0};
  const double max_edge = 0.1;
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = max_edge});
  expect_well_formed(mesh);
  EXPECT_GT(mesh.triangles.size(), 200u);

  double total_area = 0;
  for (const Triangle& t : mesh.triangles) {
    total_area += area(mesh.positions, t);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(length(mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]), max_edge);
    }
    EXPECT_NEAR(geometric_normal(mesh.positions, t).z, 1.0, 1e-12);  // winding kept
  }
  EXPECT_NEAR(total_area, 1.0, 1e-9);

  // Conforming: interior edges are used by exactly two triangles, boundary edges by one.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> use;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      ++use[std::minmax(t[k], t[(k + 1) % 3])];
    }
  }
  const auto on_border = [](Vec3 a, Vec3 b) {
    return (a.x == 0 && b.x == 0) || (a.x == 1 && b.x == 1) || (a.y == 0 && b.y == 0) ||
           (a.y == 1 && b.y == 1);
  };
  int boundary = 0;
  for (const auto& [edge, count] : use) {
    const bool border = on_border(mesh.positions[edge.first], mesh.positions[edge.second]);
    EXPECT_EQ(count, border ? 1 : 2);
    boundary += border;
  }
  EXPECT_GE(boundary, 4 * 10);
  // Every vertex is shared: no duplicated positions on a flat single-material quad.
  std::set<PositionKey> distinct;
  for (const Vec3& p : mesh.positions) distinct.insert(key(p));
  EXPECT_EQ(distinct.size(), mesh.positions.size());
}

TEST(MeshPreparation, SubdividedClosedCubeStaysWatertightAcrossCreases) {
  const PreparedMesh mesh = prepare_mesh(cube_soup(), {.max_edge = 0.15, .crease_deg = 30});
  expect_well_formed(mesh);
  double total_area = 0;
  for (const Triangle& t : mesh.triangles) total_area += area(mesh.positions, t);
  EXPECT_NEAR(total_area, 6.0, 1e-9);
  for (const auto& [edge, count] : edge_use(mesh)) EXPECT_EQ(count, 2);
  for (const Vec3& n : mesh.normals) {
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0, 1e-12);
  }
}

TEST(MeshPreparation, WindingIsPreservedTriangleByTriangle) {
  TriangleSoup soup = sphere_soup(1.0, 12, 6);
  // Flip every other triangle: preparation must keep each one's own orientation.
  for (std::size_t t = 0; t < soup.triangles.size(); t += 2) {
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
  }
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = 0});
  expect_well_formed(mesh);
  ASSERT_EQ(mesh.triangles.size(), soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    EXPECT_NEAR(dot(geometric_normal(mesh.positions, mesh.triangles[t]),
                    geometric_normal(soup.positions, soup.triangles[t])),
                1.0, 1e-12);
  }
}

TEST(MeshPreparation, VertexNormalsDoNotChangeWithSubdivision) {
  // Angle weighting: an original vertex keeps its normal however its faces are split.
  const TriangleSoup soup = sphere_soup(1.0, 8, 5);
  const PreparedMesh coarse = prepare_mesh(soup, {.max_edge = 0, .crease_deg = 60});
  const PreparedMesh fine = prepare_mesh(soup, {.max_edge = 0.05, .crease_deg = 60});
  expect_well_formed(fine);
  std::map<PositionKey, Vec3> fine_normal;
  for (std::size_t v = 0; v < fine.positions.size(); ++v) {
    fine_normal[key(fine.positions[v])] = fine.normals[v];
  }
  for (std::size_t v = 0; v < coarse.positions.size(); ++v) {
    const Vec3 n = fine_normal.at(key(coarse.positions[v]));
    EXPECT_NEAR(dot(n, coarse.normals[v]), 1.0, 1e-12);
  }
}

TEST(MeshPreparation, SharpConeTipNormalsStayInFrontOfEveryFace) {
  // A needle cone smoothed with a generous crease: its faces bend through almost 360 degrees
  // around the tip, so their mean normal is behind some of them; those get their own vertex.
  TriangleSoup soup;
  const int sides = 64;
  const Vec3 tip{0, 0, 1000};
  for (int i = 0; i < sides; ++i) {
    const double a0 = 2 * kPi * i / sides, a1 = 2 * kPi * (i + 1) / sides;
    add_separate(soup, tip, {std::cos(a0), std::sin(a0), 0}, {std::cos(a1), std::sin(a1), 0});
  }
  const PreparedMesh mesh = prepare_mesh(soup, {.max_edge = 0, .crease_deg = 60});
  expect_well_formed(mesh);
  EXPECT_GT(mesh.positions.size(), std::size_t{sides + 1});
}

TEST(MeshPreparation, EmptySoupGivesEmptyMesh) {
  const PreparedMesh mesh = prepare_mesh(TriangleSoup{}, {.max_edge = 0.1});
  EXPECT_TRUE(mesh.positions.empty());
  EXPECT_TRUE(mesh.triangles.empty());
}

TEST(MeshPreparation, MalformedSoupIsRejected) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  soup.triangles = {{0, 1, 3}};
  soup.triangle_material = {0};
  EXPECT_THROW(prepare_mesh(soup, {}), std::invalid_argument);
  soup.triangles = {{0, 1, 2}};
  soup.triangle_material = {};
  EXPECT_THROW(prepare_mesh(soup, {}), std::invalid_argument);
  soup.triangle_material = {0};
  soup.positions[1].x = std::nan("");
  EXPECT_THROW(prepare_mesh(soup, {}), std::invalid_argument);
}

TEST(MeshPreparation, HopelesslySmallMaxEdgeIsRejectedUpFront) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1000, 0, 0}, {0, 1000, 0}};
  soup.triangles = {{0, 1, 2}};
  soup.triangle_material = {0};
  EXPECT_THROW(prepare_mesh(soup, {.max_edge = 0.01}), InputError);
}

}  // namespace
}  // namespace relight
