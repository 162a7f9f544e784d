// A glossy movable object (issues 12 and 13): a brushed-steel cabinet (metallic 1, roughness
// 0.3) moved and turned through the state in a Lambertian room under a downlight and a wall
// washer. `relight render --state` — per pixel and per vertex — against `relight reference
// --state` (512 samples per pixel): 8 × 8-pixel block means of luminance within 5 % on average
// per pixel and 10 % per vertex, as the glossy room's images are held (glossy_probe_test.cpp).
// The cabinet fills most of the view, so the blocks are mostly its faces.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "agreement.h"
#include "image/image_exr.h"
#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::TempDir;

const char* kRoom = R"({
  "materials": {
    "wall": {"albedo": [0.6, 0.6, 0.6]},
    "floor": {"albedo": [0.35, 0.3, 0.25]},
    "ceiling": {"albedo": [0.8, 0.8, 0.8]},
    "steel": {"albedo": [0.8, 0.8, 0.82], "metallic": 1, "roughness": 0.3}
  },
  "geometry": [
    {"type": "quad", "corner": [0, 0, 0], "u": [0, 0, 4], "v": [4, 0, 0], "material": "floor"},
    {"type": "quad", "corner": [0, 2.6, 0], "u": [4, 0, 0], "v": [0, 0, 4], "material": "ceiling"},
    {"type": "quad", "corner": [0, 0, 0], "u": [0, 2.6, 0], "v": [0, 0, 4], "material": "wall"},
    {"type": "quad", "corner": [4, 0, 0], "u": [0, 0, 4], "v": [0, 2.6, 0], "material": "wall"},
    {"type": "quad", "corner": [0, 0, 4], "u": [0, 2.6, 0], "v": [4, 0, 0], "material": "wall"},
    {"type": "quad", "corner": [0, 0, 0], "u": [4, 0, 0], "v": [0, 2.6, 0], "material": "wall"}
  ],
  "objects": [
    {"name": "cabinet", "geometry": [{"type": "box", "min": [1.0, 0, 1.0], "max": [1.8, 1.2, 1.5], "material": "steel"}]}
  ],
  "luminaires": [
    {"name": "down", "position": [2.0, 2.55, 2.0], "aim": [0, -1, 0], "distribution": {"type": "cosine_power", "candela": 2000, "exponent": 4}},
    {"name": "wash", "position": [3.7, 1.2, 3.7], "aim": [-1, -0.3, -1], "distribution": {"type": "cosine_power", "candela": 600, "exponent": 2}}
  ],
  "precompute": {"max_edge": 0.2, "gather_rays": 256},
  "cameras": [
    {"name": "view", "eye": [3.3, 1.5, 3.4], "target": [2.0, 0.6, 2.1], "fov_deg": 45}
  ]
})";

const char* kState = R"({"objects": {"cabinet": {"translate": [0.6, 0, 0.8], "rotate_deg": 40}}})";

TEST(GlossyObject, MovedSteelCabinetRendersWithinFivePercentOfTheReferenceImage) {
  const TempDir dir;
  const fs::path scene = dir.path() / "room.json", state = dir.path() / "state.json",
                 rlt = dir.path() / "room.rlt";
  std::ofstream(scene) << kRoom;
  std::ofstream(state) << kState;
  CommandResult r =
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string size = " --width 64 --height 48 ";
  const fs::path pixel = dir.path() / "pixel.exr", vertex = dir.path() / "vertex.exr",
                 truth = dir.path() / "reference.exr";
  r = run_relight("render '" + rlt.string() + "' --state '" + state.string() + "' --direct pixel" +
                  size + "-o '" + pixel.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("render '" + rlt.string() + "' --state '" + state.string() + "'" + size + "-o '" +
                  vertex.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene.string() + "' --state '" + state.string() +
                  "' --spp 512 --seed 7" + size + "-o '" + truth.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image reference = read_exr(truth);
  const testing::BlockAgreement per_pixel = testing::compare_blocks(read_exr(pixel), reference, 8);
  const testing::BlockAgreement per_vertex =
      testing::compare_blocks(read_exr(vertex), reference, 8);
  std::printf(
      "glossy cabinet image, %d blocks: per pixel mean %.2f %%, worst %.2f %%; per vertex "
      "mean %.2f %%, worst %.2f %%\n",
      per_pixel.blocks, 100 * per_pixel.mean, 100 * per_pixel.worst, 100 * per_vertex.mean,
      100 * per_vertex.worst);
  EXPECT_TRUE(per_pixel.finite);
  EXPECT_TRUE(per_vertex.finite);
  EXPECT_EQ(per_pixel.blocks, 48);
  EXPECT_LT(per_pixel.mean, 0.05);
  EXPECT_LT(per_vertex.mean, 0.10);
}

}  // namespace
}  // namespace relight
