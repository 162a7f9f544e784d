// `relight report`: the page of a room with a window, a luminaire and a task area, with a month of
// daylight — its tables and plans, the task check, the luminaire schedule and the annual metrics
// equal to `relight annual`'s, names escaped, nothing fetched from elsewhere.
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/daylight_room.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

TEST(ReportCommand, AWindowRoomWithATaskAndAMonthOfDaylight) {
  const TempDir dir;
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  room.albedo = 0.5;
  nlohmann::json scene = testing::window_room_json(room);
  scene["luminaires"] = {testing::panel_luminaire("panel <A&B>")};
  scene["sensors"] = {
      {{"name", "desk \"north\""},
       {"grid",
        {{"corner", {0.5, 0.8, 0.5}}, {"u", {3, 0, 0}}, {"v", {0, 0, 4}}, {"nu", 3}, {"nv", 4}}},
       {"task", {{"em", 100000}, {"u0", 0.1}}}}};
  scene["maintenance_factor"] = 0.8;
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}};
  const fs::path rlt = testing::precompute_scene(dir, "room", scene.dump());
  testing::SyntheticPlace place;
  place.first_month = place.last_month = 9;
  const fs::path epw = dir.write("september.epw", testing::synthetic_epw(place));
  const fs::path html = dir.path() / "report.html";
  const auto r = run_relight("report '" + rlt.string() + "' --weather '" + epw.string() + "' -o '" +
                             html.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_text(html);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* expected :
       {"<h2>Illuminance</h2>", "<h2>Task areas (EN 12464-1)</h2>", "<h2>Luminaires</h2>",
        "<h2>A year of daylight</h2>", "desk &quot;north&quot;", "panel &lt;A&amp;B&gt;",
        "maintenance factor 0.80", "class=\"fail\">FAIL", "class=\"pass\">pass",
        "svg class=\"plan\"", "svg class=\"polar\"", "Testville", "@media print"}) {
    EXPECT_NE(page.find(expected), std::string::npos) << expected;
  }
  EXPECT_EQ(page.find("panel <A"), std::string::npos);
  // Nothing from elsewhere: no script, no link, no URL but the SVG namespace.
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  const std::regex url("(https?:)?//[a-z]");
  std::string stripped = page;
  for (std::size_t at; (at = stripped.find("http://www.w3.org/2000/svg")) != std::string::npos;) {
    stripped.erase(at, 26);
  }
  EXPECT_FALSE(std::regex_search(stripped, url));

  // The annual table is `relight annual`'s summary.
  const auto a = run_relight("annual '" + rlt.string() + "' --weather '" + epw.string() + "'");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const std::smatch m = [&] {
    std::smatch found;
    std::regex_search(a.out, found,
                      std::regex("sDA300/50% ([0-9.]+)%  ASE1000,250h ([0-9.]+)%  "
                                 "mean DA300 ([0-9.]+)%"));
    return found;
  }();
  ASSERT_EQ(m.size(), 4u) << a.out;
  EXPECT_NE(page.find("<td>" + m[1].str() + "%</td><td>" + m[2].str() + "%</td><td>" + m[3].str() +
                      "%</td>"),
            std::string::npos)
      << a.out;
}

}  // namespace
}  // namespace relight
