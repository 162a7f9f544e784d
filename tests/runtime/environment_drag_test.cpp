// A drag under a top-level environment (sources/environment/environment_objects.h): while the same
// object moves frame after frame, every receiver keeps the product of everything else and only
// the moving object's field is multiplied in again; another object starting to move makes
// those products again. Whatever the history of placements, the light equals that of a scene
// opened at the final placements (1e-5 of the brightest receiver: float sums in another order)
// — a crate dragged over two frames, then a second one, then both moved together — with the
// sky's sun traced (light/compact_sources.h). Direct light alone: the bounce converges to its
// tolerance from wherever the last frame left it, which would hide a difference of that size.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "runtime/lighting_state.h"
#include "runtime/relit_scene.h"
#include "support/precomputed_file.h"
#include "support/temp_dir.h"
#include "trace/ray_tracer.h"

namespace relight {
namespace {

nlohmann::json two_crates() {
  return nlohmann::json::parse(R"({
    "materials": {"floor": {"albedo": [0.5, 0.45, 0.4]}, "paint": {"albedo": [0.7, 0.7, 0.7]}},
    "geometry": [
      {"type": "quad", "corner": [-3, 0, -3], "u": [0, 0, 6], "v": [6, 0, 0], "material": "floor"}
    ],
    "objects": [
      {"name": "a", "geometry": [{"type": "box", "min": [-1.2, 0, -0.3], "max": [-0.6, 0.5, 0.3],
                                 "material": "paint"}]},
      {"name": "b", "geometry": [{"type": "box", "min": [0.6, 0, -0.3], "max": [1.2, 0.7, 0.3],
                                 "material": "paint"}]}
    ],
    "environment": {"type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
                    "sun": {"azimuth_deg": 225, "altitude_deg": 40}, "sun_illuminance": 60000},
    "precompute": {"max_edge": 0.25, "gather_rays": 64,
                   "cuts": {"directions": 2048, "sphere_count": 8, "sphere_points": 8}}
  })");
}

TEST(EnvironmentDrag, AnyHistoryOfPlacementsGivesTheLightOfTheFinalOne) {
  testing::TempDir dir;
  const std::filesystem::path rlt = testing::write_precomputed(dir, "crates", two_crates());
  const std::string moves[] = {
      R"({"objects": {"a": {"translate": [0.2, 0, 0.1]}}})",
      R"({"objects": {"a": {"translate": [0.4, 0, 0.3], "rotate_deg": 20}}})",
      R"({"objects": {"a": {"translate": [0.4, 0, 0.3], "rotate_deg": 20},
                      "b": {"translate": [-0.3, 0, -0.5]}}})",
      R"({"objects": {"a": {"translate": [0.1, 0, 0.6]}, "b": {"translate": [-0.2, 0, -0.7]}}})",
  };
  RelighterSettings direct;
  direct.environment_bounce = false;
  RelitScene dragged(rlt, std::nullopt, direct);
  int k = 0;
  for (const std::string& move : moves) {
    const std::filesystem::path state = dir.write("move" + std::to_string(k++) + ".json", move);
    dragged.apply(load_lighting_state(dragged.scene(), state));
    const RelitScene fresh(rlt, state, direct);
    const std::span<const float> a = dragged.irradiance(), b = fresh.irradiance();
    ASSERT_EQ(a.size(), b.size());
    double worst = 0, scale = 0;
    for (const float v : b) scale = std::max(scale, static_cast<double>(std::abs(v)));
    for (std::size_t i = 0; i < a.size(); ++i) {
      worst = std::max(worst, std::abs(static_cast<double>(a[i]) - b[i]) / scale);
    }
    EXPECT_LT(worst, 1e-5) << move;
    EXPECT_GT(scale, 1000) << move;
  }
}

// An object turned a little every frame (a designer turning a chair) leaves nothing behind: the
// turned frames' light and leaf tables kept are those of the placement as it stands (each frame's
// turn kept for good would add ~4 MB of them).
TEST(EnvironmentDrag, TurningAnObjectFrameAfterFrameKeepsOnlyTheCurrentTurnsTables) {
  testing::TempDir dir;
  const std::filesystem::path rlt = testing::write_precomputed(dir, "crates", two_crates());
  RelighterSettings direct;
  direct.environment_bounce = false;
  RelitScene relit(rlt, std::nullopt, direct);
  std::size_t most = 0;
  for (int frame = 1; frame <= 12; ++frame) {
    const std::string move = R"({"objects": {"a": {"rotate_deg": )" + std::to_string(3 * frame) +
                             R"(}, "b": {"rotate_deg": -10}}})";
    relit.apply(load_lighting_state(relit.scene(),
                                    dir.write("turn" + std::to_string(frame) + ".json", move)));
    most = std::max(most, relit.relighter().environment()->objects_kept_turns());
  }
  std::printf("at most %zu turned frames and leaf tables kept over 12 turns\n", most);
  EXPECT_GT(most, 0u);
  EXPECT_LE(most, 8u);  // 6: two frames (a, b), four relative turns
}

// The tracer of what a camera sees (RelitScene::shown_tracer): kept while the placements stay
// (a view frame moves only the eye), made again when an object moves, and then hitting the
// object where it now stands: a ray down onto crate a's top meets it (an id after the mesh's
// triangles) until the crate moves 1 m aside, then the floor.
TEST(EnvironmentDrag, ShownTracerIsKeptWhileThePlacementsStayAndFollowsAMovedObject) {
  testing::TempDir dir;
  const std::filesystem::path rlt = testing::write_precomputed(dir, "crates", two_crates());
  RelitScene relit(rlt, std::nullopt);
  const std::size_t mesh_triangles = relit.transfer().triangles.size();
  const Ray down{{-0.9, 2, 0}, {0, -1, 0}};
  const RayTracer* first = &relit.shown_tracer();
  const RayHit on_crate = first->intersect(down);
  ASSERT_TRUE(on_crate.hit());
  EXPECT_GE(on_crate.triangle, mesh_triangles);
  EXPECT_NEAR(on_crate.t, 1.5, 1e-4);
  EXPECT_EQ(&relit.shown_tracer(), first);  // kept
  relit.apply(load_lighting_state(
      relit.scene(), dir.write("aside.json", R"({"objects": {"a": {"translate": [0, 0, 1]}}})")));
  const RayHit on_floor = relit.shown_tracer().intersect(down);
  ASSERT_TRUE(on_floor.hit());
  EXPECT_LT(on_floor.triangle, mesh_triangles);
  EXPECT_NEAR(on_floor.t, 2, 1e-4);
  const RayHit moved = relit.shown_tracer().intersect({{-0.9, 2, 1}, {0, -1, 0}});
  ASSERT_TRUE(moved.hit());
  EXPECT_GE(moved.triangle, mesh_triangles);
  EXPECT_NEAR(moved.t, 1.5, 1e-4);
}

}  // namespace
}  // namespace relight
