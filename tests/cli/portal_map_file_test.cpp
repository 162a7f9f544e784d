// A .rlt keeps a map environment's path, not the image (docs/decisions.md): a state that uses the
// map after the file moved is an input error naming the portal's environment.
#include <filesystem>

#include <gtest/gtest.h>

#include "run_command.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

using testing::run_relight;
using testing::TempDir;

TEST(PortalMapFile, AMovedMapIsAnInputErrorNamingThePortal) {
  const std::filesystem::path source = "/usr/share/blender/datafiles/studiolights/world/city.exr";
  if (!std::filesystem::exists(source))
    GTEST_SKIP() << source << " not found (Debian blender-data)";
  const TempDir dir;
  std::filesystem::copy_file(source, dir.path() / "city.exr");
  testing::WindowRoom room;
  room.skylight = testing::kSkylight;
  nlohmann::json scene = testing::window_room_json(room);
  scene["portals"][0]["environment"] = {{"type", "map"}, {"file", "city.exr"}, {"scale", 1000}};
  scene["sensors"] = {{{"name", "floor"}, {"points", {{2, 0, 2.5}}}, {"normal", {0, 1, 0}}}};
  scene["precompute"] = {{"max_edge", 1}, {"gather_rays", 8}, {"sensor_gather_rays", 8}};
  const std::filesystem::path json = dir.write("room.json", scene.dump());
  const std::string rlt = (dir.path() / "room.rlt").string();
  ASSERT_EQ(
      run_relight("precompute '" + json.string() + "' -o '" + rlt + "' --no-progress").exit_code,
      0);
  EXPECT_EQ(run_relight("probe '" + rlt + "'").exit_code, 0);
  std::filesystem::rename(dir.path() / "city.exr", dir.path() / "moved.exr");
  testing::expect_input_error(run_relight("probe '" + rlt + "'"),
                              json.string() + ":/portals/0/environment: ");
}

}  // namespace
}  // namespace relight
