// An OBJ room exported with its normals out (the faces wound clockwise seen from inside) is found
// and turned by `precompute` and `reference`, which say so on stderr: its probe and its reference
// equal the correctly wound room's within 0.2 % (the same triangles, numbered in another order, so
// sampled in another order), the ceiling lit by interreflection. The correct room precomputes
// without the warning.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::sensor_lux;
using testing::TempDir;

// A 4 × 3 × 5 m box as six quads, each wound counter-clockwise seen from inside (`inward`) or
// from outside.
std::string box_obj(bool inward) {
  const double x = 4, y = 3, z = 5;
  std::string obj;
  for (int i = 0; i < 8; ++i)
    obj += "v " + std::to_string((i & 1) != 0 ? x : 0) + " " +
           std::to_string((i & 2) != 0 ? y : 0) + " " + std::to_string((i & 4) != 0 ? z : 0) + "\n";
  // Outward winding of each face (1-based vertex numbers: bit 0 x, bit 1 y, bit 2 z).
  const std::vector<std::vector<int>> faces = {{1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3},
                                               {2, 4, 8, 6}, {1, 3, 4, 2}, {5, 6, 8, 7}};
  for (std::vector<int> f : faces) {
    if (inward) f = {f[0], f[3], f[2], f[1]};  // the same diagonal as the turned outward quad
    obj += "f " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
           " " + std::to_string(f[3]) + "\n";
  }
  return obj;
}

std::string scene_json(const std::string& obj) {
  return R"({
  "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] } },
  "geometry": [ { "type": "mesh", "file": ")" +
         obj + R"(", "material": "grey" } ],
  "luminaires": [ { "name": "down", "position": [2, 2.9, 2.5],
                    "distribution": { "type": "cosine_power", "candela": 900, "exponent": 2 } } ],
  "sensors": [
    { "name": "work plane", "grid": { "corner": [0.5, 0.8, 0.5], "u": [3, 0, 0], "v": [0, 0, 4],
                                      "nu": 3, "nv": 4 } },
    { "name": "ceiling", "points": [[1, 2.99, 1], [3, 2.99, 4]], "normal": [0, -1, 0] } ],
  "precompute": { "gather_rays": 64, "max_edge": 0.5 }
})";
}

struct Outputs {
  std::vector<double> probe, reference;
  std::string precompute_err, reference_err;
};

Outputs run_room(const TempDir& dir, const std::string& name, bool inward) {
  dir.write(name + ".obj", box_obj(inward));
  const fs::path scene = dir.write(name + ".json", scene_json(name + ".obj"));
  const fs::path rlt = dir.path() / (name + ".rlt"), probe = dir.path() / (name + "-probe.csv"),
                 reference = dir.path() / (name + "-reference.csv");
  Outputs out;
  auto r =
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  out.precompute_err = r.err;
  r = run_relight("probe '" + rlt.string() + "' -o '" + probe.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene.string() + "' --spp 64 --seed 3 --sensors-out '" +
                  reference.string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  out.reference_err = r.err;
  out.probe = sensor_lux(probe);
  out.reference = sensor_lux(reference);
  return out;
}

void expect_same(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 14u);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 2e-3 * std::abs(b[i])) << i;
}

TEST(FlippedRoom, AnObjRoomWithItsNormalsOutIsTurnedAndLitAsTheCorrectOne) {
  TempDir dir;
  const Outputs correct = run_room(dir, "correct", true);
  const Outputs flipped = run_room(dir, "flipped", false);
  EXPECT_EQ(correct.precompute_err.find("turned"), std::string::npos) << correct.precompute_err;
  const std::string turned = "turned 12 of 12 triangles whose front faced out of the closed space";
  EXPECT_NE(flipped.precompute_err.find(turned), std::string::npos) << flipped.precompute_err;
  EXPECT_NE(flipped.reference_err.find(turned), std::string::npos) << flipped.reference_err;
  expect_same(flipped.probe, correct.probe);
  expect_same(flipped.reference, correct.reference);
  // The ceiling sees the luminaire's light only as the room reflects it.
  EXPECT_GT(correct.probe[12], 1.0);
  EXPECT_GT(correct.reference[12], 1.0);
}

}  // namespace
}  // namespace relight
