// `relight reference` on a window scene: the CLI reads the portal's map environment (an
// OpenEXR file) and the floor sensors read E = L·π·F through the window
// (tests/support/daylight_room.h).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "image/image.h"
#include "image/image_exr.h"
#include "run_command.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

TEST(ReferenceDaylightCli, WindowToConstantMapMatchesConfigurationFactor) {
  TempDir dir;
  // A constant map of 250 cd/m² (exact in half floats) scaled by 4: L = 1000 cd/m².
  write_exr(dir.path() / "sky.exr", make_image(32, 16, {250, 250, 250}));
  testing::WindowRoom room;
  room.south_window = testing::Rect{1, 3, 0.9, 2.1};
  nlohmann::json scene = testing::window_room_json(room);
  scene["portals"][0]["environment"] = {{"type", "map"}, {"file", "sky.exr"}, {"scale", 4}};
  scene["sensors"] = {{{"name", "floor"},
                       {"points", {{2, 0, 4}, {1.2, 0, 3}, {3.5, 0, 2}}},
                       {"normal", {0, 1, 0}}}};
  const auto file = dir.write("window.json", scene.dump());
  const auto csv = dir.path() / "e.csv";
  const auto r = run_relight("reference '" + file.string() +
                             "' --spp 8192 --no-progress --sensors-out '" + csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = parse_csv(read_text(csv));
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double x = std::stod(rows[i][2]), z = std::stod(rows[i][4]);
    const double expected =
        1000 * kPi * testing::perpendicular_rect_factor(1 - x, 3 - x, 0.9, 2.1, 5 - z);
    EXPECT_NEAR(std::stod(rows[i][8]), expected, 0.02 * expected) << "sensor " << i;
  }
}

}  // namespace
}  // namespace relight
