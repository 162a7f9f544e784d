// Daylight acceptance, transfer side: the precomputed direct portal transfer of a black room (no
// interreflection) against the closed forms E = L·π·F of a rectangular opening to a uniform sky
// (tests/support/daylight_room.h). A uniform shell of luminance L gives every receiver
// E = L·Σ_cells t̂ (its decoded cubemap record, as the run time's dot product with a constant
// cubemap) and, from the SH-basis direct columns that feed the bounce solver, E = L·√(4π)·S_r,00.
// Both are checked at floor sensors (centre, off-centre, near a wall) and over every floor vertex.
// Run time, interreflection and the reference tracer: tests/render/daylight_accuracy_test.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/receivers.h"
#include "scene/scene_loader.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/portal_direct.h"
#include "sources/portals/portal_geometry.h"
#include "sources/precompute.h"
#include "support/daylight_room.h"
#include "trace/traced_scene.h"

namespace relight {
namespace {

using nlohmann::json;
using testing::parallel_rect_factor;
using testing::perpendicular_rect_factor;
using testing::Rect;
using testing::WindowRoom;

constexpr double kLuminance = 1000;  // cd/m², the placeholder sky of window_room_json

// Room 4 × 3 × 5 m (tests/support/daylight_room.h): skylight x ∈ [1.5, 2.5], z ∈ [2, 3.5];
// south window (wall z = 5) x ∈ [1, 3], y ∈ [0.9, 2.1].
using testing::kSkylight;
using testing::kWindow;
using testing::skylight_factor;
using testing::window_factor;

json floor_sensors(const std::vector<Vec3>& points) {
  json p = json::array();
  for (Vec3 v : points) p.push_back({v.x, v.y, v.z});
  return json::array({{{"name", "floor"}, {"points", p}, {"normal", {0, 1, 0}}}});
}

// A black room with the given opening, floor sensors and a cheap precompute (no
// interreflection to gather in a black room).
json black_room(const WindowRoom& room, const std::vector<Vec3>& points) {
  json scene = testing::window_room_json(room);
  scene["sensors"] = floor_sensors(points);
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 4}, {"sensor_gather_rays", 4}};
  return scene;
}

struct PortalCase {
  Scene scene;
  Precomputed precomputed;
  Eigen::MatrixXf sh_columns;  // of portal 0, recomputed (the precompute drops them)
};

PortalCase precompute_case(const json& document) {
  PortalCase c{scene_from_json(document, "portal.json"), {}, {}};
  PrecomputeOptions options;
  options.progress = false;
  c.precomputed = precompute_transfer(c.scene, options);
  // The SH-basis direct columns with the precompute's own settings and seed.
  const Precomputed& p = c.precomputed;
  const TracedScene traced = build_traced_scene(p.mesh, c.scene.materials);
  std::vector<std::uint8_t> skip = portal_vertices(p.mesh, c.scene.materials);
  skip.resize(p.receivers.size(), 0);
  PortalDirectSettings settings;
  settings.face_size = c.scene.precompute.portal_face_size;
  settings.sh_order = p.portal_sh_order;
  settings.samples_per_cell = c.scene.precompute.portal_samples_per_cell;
  settings.seed = options.seed + 0x9e3779b97f4a7c15ULL;
  c.sh_columns = compute_portal_direct(p.receivers, receiver_ray_points(p.receivers, p.mesh), skip,
                                       p.mesh, traced, p.portals.at(0).geometry, settings, false)
                     .sh_columns;
  return c;
}

// E at receiver r under a uniform shell of luminance L, from the stored cubemap record.
double cubemap_illuminance(const PortalCase& c, std::size_t r, double l) {
  const PortalDirect& d = c.precomputed.portals.at(0).direct;
  const std::span<const std::uint8_t> bytes(d.records.data() + d.offsets[r],
                                            d.offsets[r + 1] - d.offsets[r]);
  const std::vector<double> cells = decode_receiver_cubemap(d.face_size, bytes);
  double sum = 0;
  for (double t : cells) sum += t;
  return l * sum;
}

// The same from the SH-basis direct column of Y_00 (a uniform L is √(4π)·L·Y_00).
double sh_illuminance(const PortalCase& c, std::size_t r, double l) {
  return l * std::sqrt(4 * kPi) * c.sh_columns(static_cast<Eigen::Index>(r), 0);
}

struct Errors {
  double mean = 0, worst = 0;
  std::size_t count = 0;
};

// Sensors (each within 2%, printed) and every floor vertex the factor applies to.
void check_against_closed_form(const char* name, const PortalCase& c,
                               const std::vector<Vec3>& points, double (*factor)(Vec3),
                               bool (*vertex_ok)(Vec3)) {
  const Receivers& rec = c.precomputed.receivers;
  ASSERT_EQ(rec.sensor_count, points.size());
  for (std::size_t s = 0; s < points.size(); ++s) {
    const std::size_t r = rec.vertex_count + s;
    const double expected = kLuminance * kPi * factor(points[s]);
    const double cube = cubemap_illuminance(c, r, kLuminance);
    const double sh = sh_illuminance(c, r, kLuminance);
    std::printf(
        "%s sensor (%.2f, %.2f, %.2f): L·π·F %.3f lx, cubemap %.3f (%+.3f%%), SH %.3f (%+.3f%%)\n",
        name, points[s].x, points[s].y, points[s].z, expected, cube, 100 * (cube / expected - 1),
        sh, 100 * (sh / expected - 1));
    ::testing::Test::RecordProperty(std::string(name) + "_sensor" + std::to_string(s) + "_rel",
                                    std::to_string(cube / expected - 1));
    EXPECT_NEAR(cube, expected, 0.02 * expected) << name << " sensor " << s;
    EXPECT_NEAR(sh, expected, 0.02 * expected) << name << " sensor " << s << " (SH column)";
  }
  Errors cube, sh;
  for (std::size_t v = 0; v < rec.vertex_count; ++v) {
    const Vec3 p = rec.positions[v];
    if (std::abs(p.y) > 1e-9 || rec.normals[v].y < 0.999 || !vertex_ok(p)) continue;
    const double expected = kLuminance * kPi * factor(p);
    const double ec = std::abs(cubemap_illuminance(c, v, kLuminance) / expected - 1);
    const double es = std::abs(sh_illuminance(c, v, kLuminance) / expected - 1);
    cube.mean += ec;
    sh.mean += es;
    cube.worst = std::max(cube.worst, ec);
    sh.worst = std::max(sh.worst, es);
    ++cube.count;
  }
  ASSERT_GT(cube.count, 20u);
  cube.mean /= cube.count;
  sh.mean /= cube.count;
  std::printf(
      "%s: %zu floor vertices, relative error cubemap mean %.4f worst %.4f, SH mean %.4f worst "
      "%.4f\n",
      name, cube.count, cube.mean, cube.worst, sh.mean, sh.worst);
  ::testing::Test::RecordProperty(std::string(name) + "_vertices_worst",
                                  std::to_string(cube.worst));
  EXPECT_LE(cube.worst, 0.02) << name;
  EXPECT_LE(sh.worst, 0.02) << name;
}

TEST(PortalTransfer, SkylightDirectCubemapsGiveLPiFWithinTwoPercent) {
  WindowRoom room;
  room.skylight = kSkylight;
  // Centre, under an edge, off-centre toward a corner, and near the east wall.
  const std::vector<Vec3> points = {
      {2, 0, 2.75}, {1.5, 0, 2}, {0.6, 0, 1}, {3.5, 0, 4.5}, {3.9, 0, 2.5}};
  const PortalCase c = precompute_case(black_room(room, points));
  check_against_closed_form("skylight", c, points, skylight_factor, [](Vec3) { return true; });
}

TEST(PortalTransfer, SouthWindowDirectCubemapsGiveLPiFWithinTwoPercent) {
  WindowRoom room;
  room.south_window = kWindow;
  // In front of the window, off-centre, deep in the room, and near the west wall.
  const std::vector<Vec3> points = {{2, 0, 4}, {1.2, 0, 3.5}, {3.6, 0, 2},
                                    {2, 0, 1}, {0.1, 0, 3},   {3.8, 0, 4.6}};
  const PortalCase c = precompute_case(black_room(room, points));
  // Floor vertices on the window's wall lie in its plane (F = 0): left out.
  check_against_closed_form("south window", c, points, window_factor,
                            [](Vec3 p) { return p.z < 4.99; });
}

TEST(PortalTransfer, BlackRoomHasNoIndirectResponse) {
  // Albedo 0: nothing is reflected, so every stored SH-basis indirect response is 0.
  WindowRoom room;
  room.south_window = kWindow;
  const PortalCase c = precompute_case(black_room(room, {{2, 0, 4}}));
  const BlockedTransfer t = c.precomputed.portals.at(0).indirect.view();
  std::vector<float> values(t.size());
  t.copy_to(0, values);
  ASSERT_FALSE(values.empty());
  double largest = 0;
  for (float v : values) largest = std::max(largest, std::abs(double(v)));
  EXPECT_EQ(largest, 0.0);
}

TEST(PortalTransfer, ThePiecesConesAndTheBvhAgreeWithAndWithoutAnotherPortal) {
  // Whether a direction passes the portal, by its convex pieces' cones or by a ray into the
  // portals' BVH (sources/portals/portal_direct.h): the same cells and the same jitter, so the
  // same values — except where a cell's corner direction grazes the window's edge exactly (a
  // floor vertex in line with a jamb: the cones count it in, Embree may not), which moves that
  // cell between the coarse and the fine grid: 11 % of this room's lit receivers, within 0.6 %.
  // With the skylight as a second portal, the window's directions must also meet the window
  // before the skylight.
  for (const bool skylight : {false, true}) {
    WindowRoom room;
    room.south_window = kWindow;
    if (skylight) room.skylight = kSkylight;
    const Scene scene = scene_from_json(black_room(room, {{2, 0, 4}}), "portal.json");
    const PreparedMesh mesh = prepare_scene_mesh(scene);
    const Receivers receivers = make_receivers(scene, mesh);
    const TracedScene traced = build_traced_scene(mesh, scene.materials);
    std::vector<std::uint8_t> skip = portal_vertices(mesh, scene.materials);
    skip.resize(receivers.size(), 0);
    const std::vector<PortalGeometry> portals = portal_geometry(scene, mesh);
    ASSERT_EQ(portals.size(), skylight ? 2u : 1u);
    PortalDirectSettings settings;
    settings.samples_per_cell = 4;
    const auto direct = [&](std::size_t max_cone_edges) {
      settings.max_cone_edges = max_cone_edges;
      return compute_portal_direct(receivers, receiver_ray_points(receivers, mesh), skip, mesh,
                                   traced, portals.back(), settings, false);
    };
    const PortalDirect cones = direct(64), bvh = direct(0);
    std::size_t lit = 0, same = 0;
    double total_cones = 0, total_bvh = 0, worst = 0;
    for (std::size_t r = 0; r < receivers.size(); ++r) {
      const auto row = static_cast<Eigen::Index>(r);
      const double a = cones.sh_columns(row, 0), b = bvh.sh_columns(row, 0);
      if (a == 0 && b == 0) continue;
      ++lit;
      same += cones.sh_columns.row(row) == bvh.sh_columns.row(row) ? 1 : 0;
      total_cones += a;
      total_bvh += b;
      worst = std::max(worst, std::abs(a - b) / std::max(std::abs(a), std::abs(b)));
    }
    std::printf("%s: %zu lit receivers, %zu the same, worst %.4f, totals %.6f / %.6f\n",
                skylight ? "window and skylight" : "window", lit, same, worst, total_cones,
                total_bvh);
    EXPECT_GT(lit, receivers.size() / 4) << skylight;
    EXPECT_GT(same, lit * 85 / 100) << skylight;
    EXPECT_LT(worst, 0.015) << skylight;
    EXPECT_NEAR(total_cones, total_bvh, 1e-3 * total_bvh) << skylight;
    EXPECT_LT(cones.rays, bvh.rays) << skylight;
  }
}

}  // namespace
}  // namespace relight
