// Glossy surfaces through the transfer (their acceptance): a 5 × 4 × 2.8 m room with a polished
// metal floor (metallic 1, roughness 0.3) and a satin dielectric wall (roughness 0.2), a narrow
// downlight and a wall washer.
//  - `relight probe` within 3 % mean and 10 % worst of `relight reference` (131,072 samples per
//    sensor) on the ceiling, the walls and the table. Without the glossy first bounce
//    (engine/glossy_first_bounce.h) the ceiling above the polished floor comes out 13 % low on
//    average (the floor's reflection of the downlight spread as a diffuse surface's); the same
//    room all Lambertian is within 1.4 % mean at these settings (SH order 12 and 512 gather
//    rays: the narrow beam needs them).
//  - `relight render --direct pixel` (EXR) against the reference image (1,024 samples per
//    pixel): 8 × 8-pixel block means of luminance within 5 % on average; the default per-vertex
//    render (glossy vertices shaded toward the eye) within 10 %.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "agreement.h"
#include "image/image_exr.h"
#include "run_command.h"
#include "support/scene_json.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::sensor_lux;
using testing::TempDir;

const char* kRoom = R"({
  "materials": {
    "white": {"albedo": [0.7, 0.7, 0.7]},
    "ceiling": {"albedo": [0.8, 0.8, 0.8]},
    "metal floor": {"albedo": [0.9, 0.9, 0.9], "metallic": 1, "roughness": 0.3},
    "satin wall": {"albedo": [0.6, 0.5, 0.4], "metallic": 0, "roughness": 0.2},
    "table": {"albedo": [0.5, 0.4, 0.3]}
  },
  "geometry": [
    {"type": "quad", "corner": [0, 0, 0], "u": [0, 0, 4], "v": [5, 0, 0], "material": "metal floor"},
    {"type": "quad", "corner": [0, 2.8, 0], "u": [5, 0, 0], "v": [0, 0, 4], "material": "ceiling"},
    {"type": "quad", "corner": [0, 0, 0], "u": [0, 2.8, 0], "v": [0, 0, 4], "material": "satin wall"},
    {"type": "quad", "corner": [5, 0, 0], "u": [0, 0, 4], "v": [0, 2.8, 0], "material": "white"},
    {"type": "quad", "corner": [0, 0, 4], "u": [0, 2.8, 0], "v": [5, 0, 0], "material": "white"},
    {"type": "quad", "corner": [0, 0, 0], "u": [5, 0, 0], "v": [0, 2.8, 0], "material": "white"},
    {"type": "box", "min": [3.2, 0, 2.4], "max": [4.4, 0.75, 3.2], "material": "table"}
  ],
  "luminaires": [
    {"name": "down", "position": [2.0, 2.75, 1.6], "aim": [0, -1, 0], "distribution": {"type": "cosine_power", "candela": 3000, "exponent": 6}},
    {"name": "wash", "position": [0.6, 2.6, 3.0], "aim": [-0.4, -1, 0], "distribution": {"type": "cosine_power", "candela": 800, "exponent": 2}}
  ],
  "sensors": [
    {"name": "ceiling", "normal": [0, -1, 0], "grid": {"corner": [0.3, 2.79, 0.3], "u": [4.4, 0, 0], "v": [0, 0, 3.4], "nu": 5, "nv": 4}},
    {"name": "west wall", "normal": [1, 0, 0], "grid": {"corner": [0.01, 0.4, 0.3], "u": [0, 2.0, 0], "v": [0, 0, 3.4], "nu": 3, "nv": 4}},
    {"name": "east wall", "normal": [-1, 0, 0], "grid": {"corner": [4.99, 0.4, 0.3], "u": [0, 2.0, 0], "v": [0, 0, 3.4], "nu": 3, "nv": 4}},
    {"name": "table", "normal": [0, 1, 0], "grid": {"corner": [3.3, 0.76, 2.5], "u": [1.0, 0, 0], "v": [0, 0, 0.6], "nu": 3, "nv": 2}}
  ],
  "precompute": {
    "max_edge": 0.2,
    "gather_rays": 512,
    "sensor_gather_rays": 1024,
    "sh_order": 12
  },
  "cameras": [
    {"name": "view", "eye": [4.6, 1.6, 3.7], "target": [1.5, 0.3, 1.0], "fov_deg": 70}
  ]
})";

using testing::Agreement;

// Relative differences of `relight probe` on `rlt` from `relight reference` on `scene` (spp
// samples per sensor, seed), over its 50 sensors; files go to `dir`.
Agreement probe_against_reference(const fs::path& scene, const fs::path& rlt, int spp, int seed,
                                  const fs::path& dir) {
  const fs::path probe = dir / "probe.csv", reference = dir / "reference.csv";
  CommandResult r = run_relight("probe '" + rlt.string() + "' -o '" + probe.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene.string() + "' --spp " + std::to_string(spp) + " --seed " +
                  std::to_string(seed) + " --sensors-out '" + reference.string() +
                  "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> fast = sensor_lux(probe);
  EXPECT_EQ(fast.size(), 50u);
  return testing::relative_agreement(fast, sensor_lux(reference));
}

class GlossyRoom : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    scene_ = dir_->path() / "glossy-room.json";
    rlt_ = dir_->path() / "glossy-room.rlt";
    std::ofstream(scene_) << kRoom;
    const CommandResult r = run_relight("precompute '" + scene_.string() + "' -o '" +
                                        rlt_.string() + "' --no-progress");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { dir_.reset(); }
  static std::unique_ptr<TempDir> dir_;
  static fs::path scene_, rlt_;
};

std::unique_ptr<TempDir> GlossyRoom::dir_;
fs::path GlossyRoom::scene_, GlossyRoom::rlt_;

TEST_F(GlossyRoom, ProbeWithinThreePercentMeanAndTenWorstOfTheReference) {
  const Agreement a = probe_against_reference(scene_, rlt_, 131072, 3, dir_->path());
  std::printf("glossy room: probe vs reference mean %.2f %%, worst %.2f %%\n", 100 * a.mean,
              100 * a.worst);
  EXPECT_LT(a.mean, 0.03);
  EXPECT_LT(a.worst, 0.10);
}

TEST_F(GlossyRoom, RenderedBlocksWithinFivePercentOfTheReferenceImageOnAverage) {
  const fs::path fast = dir_->path() / "render.exr", truth = dir_->path() / "reference.exr";
  CommandResult r =
      run_relight("render '" + rlt_.string() + "' --direct pixel --width 96 --height 72 -o '" +
                  fast.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene_.string() +
                  "' --spp 1024 --seed 5 --width 96 --height 72 -o '" + truth.string() +
                  "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image a = read_exr(fast), b = read_exr(truth);
  ASSERT_EQ(a.width, 96);
  ASSERT_EQ(b.height, 72);
  const testing::BlockAgreement blocks = testing::compare_blocks(a, b, 8);
  EXPECT_TRUE(blocks.finite);
  std::printf("glossy room image: %d blocks, mean %.2f %%, worst %.2f %%\n", blocks.blocks,
              100 * blocks.mean, 100 * blocks.worst);
  EXPECT_LT(blocks.mean, 0.05);
  // The default per-vertex render: glossy vertices send their own luminance toward the eye
  // (the highlights and the room's reflection evaluated at the vertex, interpolated).
  const fs::path vertex = dir_->path() / "vertex.exr";
  r = run_relight("render '" + rlt_.string() + "' --width 96 --height 72 -o '" + vertex.string() +
                  "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const testing::BlockAgreement per_vertex = testing::compare_blocks(read_exr(vertex), b, 8);
  EXPECT_TRUE(per_vertex.finite);
  std::printf("glossy room image per vertex: mean %.2f %%, worst %.2f %%\n", 100 * per_vertex.mean,
              100 * per_vertex.worst);
  EXPECT_LT(per_vertex.mean, 0.10);
}

// The same room with its south wall opened by a window, a CIE clear sky and a 60,000 lx sun at
// 35° whose patch lies on the polished floor, no luminaires: the exact sun's first glossy
// bounce (sources/portals/portal_lighting.h) lights the ceiling. Probe within 4 % mean and
// 12 % worst of a 524,288-sample reference (measured 3.0 %, 10.5 %; a 65,536-sample reference
// is itself 3.4 % and 15.7 % off this one: the sun's reflection reaches a sensor only through a
// cosine ray that lands where the floor's lobe points at the sun).
std::string sun_room() {
  nlohmann::json room = nlohmann::json::parse(kRoom);
  room.erase("cameras");
  room["luminaires"] = nlohmann::json::array();
  testing::open_south_window(room, {.z = 4,
                                    .width = 5,
                                    .height = 2.8,
                                    .x0 = 1.5,
                                    .x1 = 3.5,
                                    .y0 = 0.9,
                                    .y1 = 2.3,
                                    .wall = "white",
                                    .sky_lux = 12000,
                                    .altitude_deg = 35,
                                    .sun_lux = 60000});
  room["precompute"]["portal_face_size"] = 16;
  return room.dump(2);
}

TEST(GlossySun, ProbeWithinFourPercentMeanAndTwelveWorstOfTheReference) {
  TempDir dir;
  const fs::path scene = dir.path() / "sun-room.json", rlt = dir.path() / "sun-room.rlt";
  std::ofstream(scene) << sun_room();
  const CommandResult r =
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Agreement a = probe_against_reference(scene, rlt, 524288, 8, dir.path());
  std::printf("sunlit glossy room: probe vs reference mean %.2f %%, worst %.2f %%\n", 100 * a.mean,
              100 * a.worst);
  EXPECT_LT(a.mean, 0.04);
  EXPECT_LT(a.worst, 0.12);
}

}  // namespace
}  // namespace relight
