// A portal's convex pieces and their cones (sources/portals/portal_outline.h): a subdivided
// window is one quadrilateral, separate windows are separate pieces, a non-convex window keeps
// its triangles, and the cones answer exactly as the triangles do.
#include "sources/portals/portal_outline.h"

#include <cmath>

#include <gtest/gtest.h>

#include "math/sampling.h"
#include "scene/scene_loader.h"
#include "sources/portals/portal_geometry.h"

namespace relight {
namespace {

// The glass quads given, each {corner, u, v}, under max_edge 0.1 m.
struct Windows {
  Scene scene;
  PreparedMesh mesh;
  PortalGeometry portal;
};

Windows windows(const nlohmann::json& quads) {
  nlohmann::json doc = nlohmann::json::parse(R"({
    "materials": { "wall": { "albedo": [0.5, 0.5, 0.5] },
                   "glass": { "albedo": [0, 0, 0], "portal": true } },
    "geometry": [ { "type": "quad", "corner": [-5, -1, -5], "u": [0, 0, 10], "v": [10, 0, 0],
                    "material": "wall" } ],
    "portals": [ { "name": "south", "material": "glass",
                   "environment": { "type": "uniform", "luminance": 1000 } } ]
  })");
  for (const auto& q : quads) {
    doc["geometry"].push_back(
        {{"type", "quad"}, {"corner", q[0]}, {"u", q[1]}, {"v", q[2]}, {"material", "glass"}});
  }
  Windows w{scene_from_json(doc, "w.json"), {}, {}};
  w.mesh = prepare_mesh(w.scene.geometry, {0.1, 30});
  w.portal = portal_geometry(w.scene, w.mesh).at(0);
  return w;
}

double piece_area(const PortalPiece& p) {
  Vec3 twice{0, 0, 0};
  for (std::size_t k = 1; k + 1 < p.size(); ++k)
    twice = twice + cross(p[k] - p[0], p[k + 1] - p[0]);
  return 0.5 * length(twice);
}

// Whether the ray (o, d) meets one of the portal's triangles (Möller & Trumbore 1997).
bool meets_triangles(const Windows& w, Vec3 o, Vec3 d) {
  for (const std::uint32_t t : w.portal.triangles) {
    const Triangle& tri = w.mesh.triangles[t];
    const Vec3 a = w.mesh.positions[tri[0]];
    const Vec3 e1 = w.mesh.positions[tri[1]] - a, e2 = w.mesh.positions[tri[2]] - a;
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-15) continue;
    const Vec3 s = o - a;
    const double u = dot(s, p) / det;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && dot(e2, q) / det > 0) return true;
  }
  return false;
}

TEST(PortalOutline, ASubdividedWindowIsOneQuadrilateralWithItsCorners) {
  const Windows w = windows(nlohmann::json::parse(R"([[[1, 0.5, 2], [0, 1.5, 0], [2.4, 0, 0]]])"));
  ASSERT_GT(w.portal.triangles.size(), 100u);  // cut to 0.1 m
  ASSERT_EQ(w.portal.pieces.size(), 1u);
  const PortalPiece& piece = w.portal.pieces[0];
  ASSERT_EQ(piece.size(), 4u);
  for (const Vec3 corner : {Vec3{1, 0.5, 2}, Vec3{1, 2, 2}, Vec3{3.4, 0.5, 2}, Vec3{3.4, 2, 2}}) {
    double nearest = 1e9;
    for (const Vec3& v : piece) nearest = std::min(nearest, length(v - corner));
    EXPECT_LT(nearest, 1e-9);
  }
  EXPECT_NEAR(piece_area(piece), 3.6, 1e-9);
}

TEST(PortalOutline, SeparateWindowsArePiecesEachAndAnLShapeKeepsItsTriangles) {
  const Windows two = windows(nlohmann::json::parse(
      R"([[[0, 0.5, 2], [0, 1, 0], [1, 0, 0]], [[2, 0.5, 2], [0, 1, 0], [1, 0, 0]]])"));
  ASSERT_EQ(two.portal.pieces.size(), 2u);
  EXPECT_NEAR(piece_area(two.portal.pieces[0]) + piece_area(two.portal.pieces[1]), 2.0, 1e-9);
  // An L: a 2 × 1 and a 1 × 1 quad sharing half an edge.
  const Windows l = windows(nlohmann::json::parse(
      R"([[[0, 0, 2], [0, 1, 0], [2, 0, 0]], [[0, 1, 2], [0, 1, 0], [1, 0, 0]]])"));
  // Its hull would be 3.5 m²: the pieces are its triangles, or its two quads.
  EXPECT_GE(l.portal.pieces.size(), 2u);
  double area = 0;
  for (const PortalPiece& p : l.portal.pieces) area += piece_area(p);
  EXPECT_NEAR(area, 3.0, 1e-9);
}

TEST(PortalOutline, ConesAnswerAsTheTrianglesDoForRandomRays) {
  const Windows w = windows(nlohmann::json::parse(
      R"([[[0, 0.5, 2], [0, 1.5, 0], [2.4, 0, 0]], [[3, 0.5, 2], [0, 1, 0], [0.5, 0, 0]],
          [[0, 0, 0], [0, 1, 0], [2, 0, 0]], [[0, 1, 0], [0, 1, 0], [1, 0, 0]]])"));
  ASSERT_LT(w.portal.pieces.size(), 20u);
  Pcg32 rng(5, 1);
  PieceCones cones;
  int through = 0;
  for (int o = 0; o < 50; ++o) {
    const Vec3 origin{-2 + 7 * rng.next_double(), -0.5 + 3 * rng.next_double(),
                      -1 + 4 * rng.next_double()};
    cones.reset(origin, w.portal.pieces);
    for (int r = 0; r < 400; ++r) {
      const Vec3 d = sample_uniform_sphere(rng.next_double(), rng.next_double());
      const bool expected = meets_triangles(w, origin, d);
      ASSERT_EQ(cones.contains(d), expected) << "origin " << o << " ray " << r;
      through += expected ? 1 : 0;
    }
  }
  EXPECT_GT(through, 1000);  // the test meets the windows often
}

}  // namespace
}  // namespace relight
