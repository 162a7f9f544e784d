// A camera whose eye is inside a closed object sees only the back of its faces, which absorb:
// `render` (vertex and per-pixel direct) and `reference` write black pixels, not NaN ("no
// surface"), and warn on stderr naming the camera; a camera in the room writes no warning and
// still shows its lit surfaces.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image/image_exr.h"
#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::TempDir;

const char* kRoomWithABox = R"({
  "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] }, "wood": { "albedo": [0.5, 0.4, 0.3] } },
  "geometry": [
    { "type": "box", "min": [0, 0, 0], "max": [4, 3, 4], "normals": "inward", "material": "grey" },
    { "type": "box", "min": [1, 0, 1], "max": [2, 1, 2], "material": "wood" } ],
  "luminaires": [ { "name": "down", "position": [2, 2.9, 2],
                    "distribution": { "type": "cosine_power", "candela": 800, "exponent": 2 } } ],
  "cameras": [ { "name": "inside the box", "eye": [1.5, 0.5, 1.5], "target": [3, 0.5, 3] },
               { "name": "room", "eye": [3.5, 1.6, 3.5], "target": [1.5, 0.5, 1.5] } ],
  "precompute": { "gather_rays": 32, "max_edge": 0.5 }
})";

struct Pixels {
  std::size_t finite = 0, lit = 0, total = 0;
};
Pixels count(const fs::path& exr) {
  Pixels p;
  for (const Rgb& c : read_exr(exr).pixels) {
    ++p.total;
    if (std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) ++p.finite;
    if (c.g > 0) ++p.lit;
  }
  return p;
}

TEST(CameraInsideObject, RenderAndReferenceShowBlackAndWarnInsteadOfNaN) {
  TempDir dir;
  const fs::path scene = dir.write("room.json", kRoomWithABox);
  const fs::path rlt = dir.path() / "room.rlt";
  ASSERT_EQ(
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress")
          .exit_code,
      0);
  const std::string size = " --width 32 --height 20 -o ";
  const std::string warning =
      "warning: camera \"inside the box\": 100% of the pixels see only "
      "the back of surfaces";
  for (const std::string direct : {"vertex", "pixel"}) {
    const fs::path inside = dir.path() / ("inside-" + direct + ".exr");
    const auto r = run_relight("render '" + rlt.string() + "' --camera 'inside the box' --direct " +
                               direct + size + "'" + inside.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
    const Pixels p = count(inside);
    EXPECT_EQ(p.finite, p.total) << direct;
    EXPECT_EQ(p.lit, 0u) << direct;
    const fs::path room = dir.path() / ("room-" + direct + ".exr");
    const auto s = run_relight("render '" + rlt.string() + "' --camera room --direct " + direct +
                               size + "'" + room.string() + "'");
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_EQ(s.err.find("warning"), std::string::npos) << s.err;
    EXPECT_EQ(count(room).lit, count(room).total) << direct;
  }
  const fs::path traced = dir.path() / "inside-reference.exr";
  const auto r = run_relight("reference '" + scene.string() +
                             "' --camera 'inside the box' --spp 4 --no-progress" + size + "'" +
                             traced.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  const Pixels p = count(traced);
  EXPECT_EQ(p.finite, p.total);
  EXPECT_EQ(p.lit, 0u);
}

}  // namespace
}  // namespace relight
