// An image shades toward the eye only the glossy vertices its rays see (the capture paper's
// §V.B, render/relit_scene_image.h vertices_in_view): those get the very values all vertices
// would, the rest are left out — here most of a glossy floor outside a narrow view and the
// steel cabinet's far faces.
#include <gtest/gtest.h>

#include <cmath>

#include "render/relit_scene_image.h"
#include "runtime/relit_scene.h"
#include "support/precomputed_file.h"
#include "support/scene_json.h"

namespace relight {
namespace {

nlohmann::json glossy_room() {
  nlohmann::json scene = nlohmann::json::parse(R"({
    "materials": {
      "wall": {"albedo": [0.6, 0.6, 0.6]},
      "metal floor": {"albedo": [0.9, 0.9, 0.9], "metallic": 1, "roughness": 0.3},
      "steel": {"albedo": [0.8, 0.8, 0.82], "metallic": 1, "roughness": 0.3}
    },
    "objects": [
      {"name": "cabinet", "geometry": [{"type": "box", "min": [1.0, 0, 1.0], "max": [1.8, 1.2, 1.5],
                                        "material": "steel"}]}
    ],
    "luminaires": [
      {"name": "down", "position": [2.0, 2.5, 2.0], "aim": [0, -1, 0],
       "distribution": {"type": "cosine_power", "candela": 2000, "exponent": 4}}
    ],
    "precompute": {"max_edge": 0.25, "gather_rays": 16, "sensor_gather_rays": 4},
    "cameras": [{"name": "view", "eye": [3.3, 1.5, 3.4], "target": [1.4, 0.5, 1.2],
                 "fov_deg": 30}]
  })");
  scene["geometry"] = testing::quad_room(4, 2.6, 4, "metal floor", "wall", "wall");
  return scene;
}

TEST(VisibleVertices, TheImagesVerticesGetTheValuesOfAllAndTheOthersAreLeftOut) {
  const testing::TempDir dir;
  RelitScene relit(testing::write_precomputed(dir, "room", glossy_room()), std::nullopt);
  const Camera& camera = relit.scene().cameras.at(0);
  const std::vector<std::uint8_t> seen = vertices_in_view(relit, camera, 64, 48);
  constexpr int kSamples = 8;
  const std::vector<float> all = glossy_vertex_luminance(relit, camera.eye, kSamples);
  const std::vector<float> culled = glossy_vertex_luminance(relit, camera.eye, kSamples, seen);
  ASSERT_EQ(all.size(), 3 * seen.size());
  ASSERT_EQ(culled.size(), all.size());
  std::size_t glossy = 0, shaded = 0;
  for (std::size_t v = 0; v < seen.size(); ++v) {
    if (std::isnan(all[3 * v])) {
      EXPECT_TRUE(std::isnan(culled[3 * v])) << v;
      continue;
    }
    ++glossy;
    if (!seen[v]) {
      EXPECT_TRUE(std::isnan(culled[3 * v])) << v;
      continue;
    }
    ++shaded;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(culled[3 * v + c], all[3 * v + c]) << v;
  }
  std::printf("glossy vertices lit toward the eye: %zu; in the 64 x 48 view: %zu\n", glossy,
              shaded);
  EXPECT_GT(shaded, 20u);
  EXPECT_LT(shaded, glossy / 2);  // a narrow view of a large floor
}

}  // namespace
}  // namespace relight
