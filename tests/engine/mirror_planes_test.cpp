// material/mirror_planes.h and engine/mirror_reflection.h: near-mirror triangles grouped into
// planes by key and geometry, and a light's image found through them at a receiver — the
// path's geometry against the image-source closed form, a blocker on either leg removing it.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "engine/mirror_reflection.h"

namespace relight {
namespace {

TEST(MirrorPlanes, CoplanarTrianglesOfOneKeyMakeOnePlane) {
  // A 2 × 2 floor (two triangles, key 0), a wall triangle (key 0), a floor triangle of key 1
  // and one that is no mirror (key −1).
  const std::vector<Vec3> positions{{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2},
                                    {0, 1, 0}, {0, 0, 5}, {3, 0, 5}, {3, 0, 6}};
  const std::vector<Triangle> triangles{{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {5, 7, 6}, {5, 6, 7}};
  const std::vector<std::uint32_t> ids{10, 11, 12, 13, 14};
  const std::vector<std::int64_t> keys{0, 0, 0, 1, -1};
  const std::vector<MirrorPlane> planes =
      find_mirror_planes(positions, triangles, ids, [&](std::size_t i) { return keys[i]; });
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].triangles, (std::vector<std::uint32_t>{10, 11}));
  EXPECT_NEAR(planes[0].area, 4, 1e-12);
  EXPECT_NEAR(planes[0].normal.y, 1, 1e-12);  // the floor faces up
  EXPECT_NEAR(planes[0].offset, 0, 1e-12);
  EXPECT_EQ(planes[1].triangles, (std::vector<std::uint32_t>{12}));
  EXPECT_NEAR(planes[1].normal.z, 1, 1e-12);
  EXPECT_EQ(planes[2].triangles, (std::vector<std::uint32_t>{13}));
  EXPECT_EQ(planes[2].group, 1);
  // Heights and images.
  EXPECT_NEAR(planes[0].height({1, 2.5, 1}), 2.5, 1e-12);
  const Vec3 image = planes[0].image({1, 2.5, 1});
  EXPECT_NEAR(image.y, -2.5, 1e-12);
  const std::vector<std::int32_t> of = mirror_plane_of(planes, 15);
  EXPECT_EQ(of[11], 0);
  EXPECT_EQ(of[12], 1);
  EXPECT_EQ(of[14], -1);
}

TEST(MirrorPlanes, OnlyTheLargestPlanesAreKept) {
  // 20 parallel floor triangles at different heights, the k-th of area k: the 16 largest.
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> ids;
  for (std::uint32_t k = 1; k <= 20; ++k) {
    const double y = k, s = std::sqrt(2.0 * k);
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {{0, y, 0}, {0, y, s}, {s, y, 0}});
    triangles.push_back({base, base + 1, base + 2});
    ids.push_back(k);
  }
  const std::vector<MirrorPlane> planes =
      find_mirror_planes(positions, triangles, ids, [](std::size_t) { return std::int64_t{0}; });
  ASSERT_EQ(planes.size(), kMaxMirrorPlanes);
  EXPECT_EQ(planes.front().triangles.front(), 5u);
  EXPECT_EQ(planes.back().triangles.front(), 20u);
}

// A 4 × 4 m metal floor (two triangles) and a receiver 2.8 m above it facing down.
struct MirrorRoom {
  std::vector<Vec3> positions{{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}};
  std::vector<Triangle> triangles{{0, 2, 1}, {0, 3, 2}};
  Vec3 receiver{1, 2.8, 1.5};
  std::vector<Vec3> all;  // the floor's and the extra vertices (the view points into it)
  RuntimeSceneView view(const std::vector<Triangle>& extra = {},
                        const std::vector<Vec3>& extra_positions = {}) {
    RuntimeSceneView v;
    v.opaque_triangles = triangles;
    all = positions;
    all.insert(all.end(), extra_positions.begin(), extra_positions.end());
    v.mesh_positions = all;
    v.vertex_count = all.size();
    v.receiver_positions = all;
    v.receiver_normals.assign(all.size(), Vec3{0, 1, 0});
    v.receiver_positions.push_back(receiver);
    v.receiver_normals.push_back({0, -1, 0});
    v.opaque_triangles.insert(v.opaque_triangles.end(), extra.begin(), extra.end());
    for (std::uint32_t t = 0; t < v.opaque_triangles.size(); ++t) v.opaque_ids.push_back(t);
    v.vertex_albedo.assign(3 * all.size(), 0.5f);
    return v;
  }
};

TEST(MirrorReflection, ThePathIsTheImageSourcesGeometry) {
  MirrorRoom room;
  const RuntimeScene scene(room.view(), {});
  const MetallicRoughness metal{{0.9, 0.9, 0.9}, 1, 0.05};
  const std::vector<std::int32_t> glossy_of(4, 0);
  const MirrorReflection mirrors(scene, glossy_of, std::vector<MetallicRoughness>{metal});
  ASSERT_FALSE(mirrors.empty());
  EXPECT_TRUE(mirrors.reflects(2));
  const Vec3 light{3, 2.5, 2.5};
  const std::vector<MirrorPath> paths = mirrors.trace(light);
  // The floor's own vertices lie in the plane: only the receiver above it has a path.
  ASSERT_EQ(paths.size(), 1u);
  const MirrorPath& p = paths[0];
  EXPECT_EQ(p.receiver, 4u);
  const Vec3 image{3, -2.5, 2.5};
  const Vec3 x = scene.ray_point(4);
  const Vec3 unfolded = image - x;
  const double d = length(unfolded);
  EXPECT_NEAR(p.factor, -unfolded.y / d / (d * d), 1e-6);
  // y where x–p' crosses the floor; the light's direction toward it and its incidence.
  const Vec3 y = x + unfolded * (x.y / (x.y + 2.5));
  const Vec3 emit = normalize(y - light);
  EXPECT_NEAR(p.emit[0], emit.x, 1e-5);
  EXPECT_NEAR(p.emit[1], emit.y, 1e-5);
  EXPECT_NEAR(p.emit[2], emit.z, 1e-5);
  EXPECT_NEAR(p.cos_in, -emit.y, 1e-5);
}

TEST(MirrorReflection, ABlockerOnEitherLegRemovesThePath) {
  MirrorRoom room;
  const MetallicRoughness metal{{0.9, 0.9, 0.9}, 1, 0.05};
  const Vec3 light{3, 2.5, 2.5};
  // The reflection point is at about (2.06, 0, 2.03): a small plate 1.3 m up on the way to the
  // receiver blocks its leg; one just under the light blocks the light's.
  for (const Vec3 centre : {Vec3{1.57, 1.3, 1.78}, Vec3{2.89, 2.2, 2.44}}) {
    const std::vector<Vec3> plate{centre + Vec3{-0.2, 0, -0.2}, centre + Vec3{0.2, 0, -0.2},
                                  centre + Vec3{0.2, 0, 0.2}, centre + Vec3{-0.2, 0, 0.2}};
    const std::vector<Triangle> faces{{4, 5, 6}, {4, 6, 7}, {4, 6, 5}, {4, 7, 6}};
    const RuntimeScene scene(room.view(faces, plate), {});
    std::vector<std::int32_t> glossy_of(8, -1);
    for (int v = 0; v < 4; ++v) glossy_of[static_cast<std::size_t>(v)] = 0;
    const MirrorReflection mirrors(scene, glossy_of, std::vector<MetallicRoughness>{metal});
    EXPECT_TRUE(mirrors.trace(light).empty()) << centre.x;
  }
}

TEST(MirrorReflection, ARougherSurfaceIsNoMirror) {
  MirrorRoom room;
  const RuntimeScene scene(room.view(), {});
  const MetallicRoughness rough{{0.9, 0.9, 0.9}, 1, 0.3};
  const MirrorReflection mirrors(scene, std::vector<std::int32_t>(4, 0),
                                 std::vector<MetallicRoughness>{rough});
  EXPECT_TRUE(mirrors.empty());
  EXPECT_FALSE(mirrors.reflects(0));
}

}  // namespace
}  // namespace relight
