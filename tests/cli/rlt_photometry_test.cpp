// A .rlt file keeps the photometry it was computed with: after the IES/LDT file is moved
// or deleted, the precomputed scene still relights with the same numbers.
#include <filesystem>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

using testing::read_text;
using testing::run_relight;
using testing::TempDir;

TEST(RltPhotometry, ProbeWorksAfterThePhotometryFileIsGone) {
  TempDir dir;
  std::filesystem::copy_file(
      std::filesystem::path(RELIGHT_TEST_DATA) / "photometry" / "small_axial.ldt",
      dir.path() / "lamp.ldt");
  const auto scene = dir.write("room.json", R"({
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "geometry": [ { "type": "box", "min": [0,0,0], "max": [3,2.5,3], "normals": "inward",
                    "material": "grey" } ],
    "luminaires": [ { "name": "lamp", "position": [1.5, 2.3, 1.5],
                      "distribution": { "type": "ldt", "file": "lamp.ldt" } } ],
    "sensors": [ { "name": "floor", "points": [[1.5, 0, 1.5], [0.5, 0, 0.5]] } ],
    "precompute": { "max_edge": 0.75, "gather_rays": 16, "sensor_gather_rays": 64, "sh_order": 4 }
  })");
  const auto rlt = dir.path() / "room.rlt";
  ASSERT_EQ(
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress")
          .exit_code,
      0);
  const auto before = dir.path() / "before.csv", after = dir.path() / "after.csv";
  ASSERT_EQ(run_relight("probe '" + rlt.string() + "' -o '" + before.string() + "'").exit_code, 0);
  std::filesystem::remove(dir.path() / "lamp.ldt");
  const auto r = run_relight("probe '" + rlt.string() + "' -o '" + after.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(before), read_text(after));
  EXPECT_NE(read_text(after).find("floor,0,"), std::string::npos);
}

}  // namespace
}  // namespace relight
