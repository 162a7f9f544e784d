// `relight annual`: a year of daylight from an EnergyPlus weather file.
//  * Consistency: for 20 random hours, the hourly illuminance equals `relight probe --state`
//    with that hour's Perez sky in the window within 0.1 %.
//  * The per-sensor metrics are those of the hourly values (DA300 and the UDI bands counted
//    again from --hourly-out), and the stdout summary's sDA300 those of the per-sensor DA.
//  * Bad arguments and a bad weather file: exit 2 with the file, line and field.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "light/epw_weather.h"
#include "run_command.h"
#include "support/daylight_room.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

// The south-window room (grey, albedo 0.5) with a 3 × 4 floor grid, precomputed.
struct AnnualRoom {
  TempDir dir;
  fs::path rlt, epw;
  testing::SyntheticPlace place;
  AnnualRoom() {
    rlt = testing::precompute_scene(dir, "room", testing::south_window_room(0.8).dump());
    place.first_month = 3;  // March and April: equinox suns, ~600 occupied hours
    place.last_month = 4;
    epw = dir.write("spring.epw", testing::synthetic_epw(place));
  }
};

const AnnualRoom& annual_room() {
  static const AnnualRoom room;
  return room;
}

// The probe of `rlt` with the record's Perez sky in the south window, on `state` (a
// lighting-state document, its portals' entry replaced).
std::vector<double> probe_hour(const AnnualRoom& room, const WeatherRecord& record,
                               nlohmann::json state = nlohmann::json::object()) {
  char datetime[32];
  std::snprintf(datetime, sizeof datetime, "%04d-%02d-%02dT%02d:30", record.year, record.month,
                record.day, record.hour - 1);
  nlohmann::json sky = {{"type", "perez"},
                        {"direct_normal_irradiance", record.direct_normal_irradiance},
                        {"diffuse_horizontal_irradiance", record.diffuse_horizontal_irradiance},
                        {"sun",
                         {{"latitude", room.place.latitude_deg},
                          {"longitude", room.place.longitude_deg},
                          {"utc_offset", room.place.time_zone_hours},
                          {"datetime", datetime}}}};
  if (record.dew_point_c) sky["dew_point_c"] = *record.dew_point_c;
  state["portals"] = {{"south window", {{"environment", sky}}}};
  const fs::path state_file = room.dir.write("hour.json", state.dump());
  const fs::path probe = room.dir.path() / "hour.csv";
  EXPECT_EQ(run_relight("probe '" + room.rlt.string() + "' --state '" + state_file.string() +
                        "' -o '" + probe.string() + "'")
                .exit_code,
            0);
  return testing::sensor_lux(probe);
}

// (month, day, hour) → the sensors' lux, from an --hourly-out file.
std::map<std::tuple<int, int, int>, std::vector<double>> hourly_lux(const fs::path& hourly) {
  std::map<std::tuple<int, int, int>, std::vector<double>> by_hour;
  const auto rows = parse_csv(read_text(hourly));
  EXPECT_EQ(rows.at(0),
            (std::vector<std::string>{"month", "day", "hour", "sensor", "index", "lux"}));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    by_hour[{std::stoi(rows[i][0]), std::stoi(rows[i][1]), std::stoi(rows[i][2])}].push_back(
        std::stod(rows[i][5]));
  }
  return by_hour;
}

const WeatherRecord& record_at(const WeatherFile& weather, std::tuple<int, int, int> key) {
  const auto [month, day, hour] = key;
  const auto record = std::find_if(weather.records.begin(), weather.records.end(), [&](auto& w) {
    return w.month == month && w.day == day && w.hour == hour;
  });
  if (record == weather.records.end()) throw std::runtime_error("no such record");
  return *record;
}

TEST(AnnualCommand, HourlyValuesEqualProbeWithThatHoursPerezSky) {
  const AnnualRoom& room = annual_room();
  const fs::path hourly = room.dir.path() / "hourly.csv", results = room.dir.path() / "year.csv";
  const auto r =
      run_relight("annual '" + room.rlt.string() + "' --weather '" + room.epw.string() + "' -o '" +
                  results.string() + "' --hourly-out '" + hourly.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  // (month, day, hour) → the 12 sensors' lux.
  const auto by_hour = hourly_lux(hourly);
  ASSERT_GT(by_hour.size(), 500u);
  for (const auto& [key, lux] : by_hour) ASSERT_EQ(lux.size(), 12u);

  const WeatherFile weather = parse_epw(read_text(room.epw), "spring.epw");
  std::vector<std::tuple<int, int, int>> keys;
  for (const auto& [key, lux] : by_hour) keys.push_back(key);
  std::mt19937 rng(17);
  std::shuffle(keys.begin(), keys.end(), rng);
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    const auto [month, day, hour] = keys[k];
    const std::vector<double> expected = probe_hour(room, record_at(weather, keys[k]));
    const std::vector<double>& got = by_hour.at(keys[k]);
    ASSERT_EQ(expected.size(), got.size());
    for (std::size_t s = 0; s < got.size(); ++s) {
      worst = std::max(worst, std::abs(got[s] - expected[s]) / std::max(expected[s], 1.0));
      EXPECT_NEAR(got[s], expected[s], 1e-3 * expected[s] + 0.01)
          << month << "/" << day << " hour " << hour << " sensor " << s;
    }
  }
  std::printf("[ measured ] annual vs probe over 20 hours: worst |Δ|/E %.2e\n", worst);

  // The per-sensor metrics are the hourly values counted.
  const auto metrics = parse_csv(read_text(results));
  ASSERT_EQ(metrics.size(), 13u);
  EXPECT_EQ(metrics[0],
            (std::vector<std::string>{"sensor", "index", "x", "y", "z", "da300", "udi_fell_short",
                                      "udi_useful", "udi_exceeded", "ase_hours"}));
  double da_sum = 0;
  int sda = 0;
  for (std::size_t s = 0; s < 12; ++s) {
    double da = 0, short_ = 0, useful = 0, exceeded = 0;
    for (const auto& [key, lux] : by_hour) {
      da += lux[s] >= 300;
      short_ += lux[s] < 100;
      useful += lux[s] >= 100 && lux[s] <= 2000;
      exceeded += lux[s] > 2000;
    }
    const double n = static_cast<double>(by_hour.size());
    const auto& row = metrics[s + 1];
    EXPECT_EQ(row[0], "floor");
    EXPECT_EQ(row[1], std::to_string(s));
    EXPECT_NEAR(std::stod(row[5]), da / n, 1e-6);
    EXPECT_NEAR(std::stod(row[6]), short_ / n, 1e-6);
    EXPECT_NEAR(std::stod(row[7]), useful / n, 1e-6);
    EXPECT_NEAR(std::stod(row[8]), exceeded / n, 1e-6);
    EXPECT_LE(std::stoi(row[9]), static_cast<int>(n));
    da_sum += da / n;
    sda += da / n >= 0.5;
  }
  // The window's sun patch: some floor points see more than 250 hours of direct sun in spring.
  int sunny = 0;
  for (std::size_t s = 1; s < metrics.size(); ++s) sunny += std::stoi(metrics[s][9]) > 0;
  EXPECT_GT(sunny, 0);
  char summary[64];
  std::snprintf(summary, sizeof summary, "sDA300/50%% %.1f%%", 100.0 * sda / 12);
  EXPECT_NE(r.out.find(summary), std::string::npos) << r.out;
  std::snprintf(summary, sizeof summary, "mean DA300 %.1f%%", 100.0 * da_sum / 12);
  EXPECT_NE(r.out.find(summary), std::string::npos) << r.out;
}

// Annual reads only the sensors (the suns through their importance) until a state edits
// materials, which light the sensors through the whole room: then every row is relit. Either
// way an hour equals the probe with that hour's sky and the same state, within 0.1 %.
TEST(AnnualCommand, AStateThatEditsMaterialsStillEqualsProbe) {
  const AnnualRoom& room = annual_room();
  const nlohmann::json edit = {{"materials", {{"room", {{"albedo", {0.8, 0.6, 0.3}}}}}}};
  const fs::path state = room.dir.write("edit.json", edit.dump());
  const fs::path hourly = room.dir.path() / "edit-hourly.csv";
  const auto r = run_relight("annual '" + room.rlt.string() + "' --weather '" + room.epw.string() +
                             "' --state '" + state.string() + "' --occupied 11:00-14:00 -o '" +
                             (room.dir.path() / "edit.csv").string() + "' --hourly-out '" +
                             hourly.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto by_hour = hourly_lux(hourly);
  ASSERT_GT(by_hour.size(), 100u);
  const WeatherFile weather = parse_epw(read_text(room.epw), "spring.epw");
  int checked = 0;
  for (const auto& [key, got] : by_hour) {
    if (checked == 3) break;
    if (std::get<1>(key) != 1) continue;  // three hours of the month's first day
    const std::vector<double> expected = probe_hour(room, record_at(weather, key), edit);
    ASSERT_EQ(expected.size(), got.size());
    for (std::size_t s = 0; s < got.size(); ++s) {
      EXPECT_NEAR(got[s], expected[s], 1e-3 * expected[s] + 0.01) << "sensor " << s;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(AnnualCommand, BadArgumentsAndWeatherFilesExitTwo) {
  const AnnualRoom& room = annual_room();
  const std::string base = "annual '" + room.rlt.string() + "' --weather ";
  testing::expect_input_error(
      run_relight(base + "'" + room.epw.string() + "' --occupied 18:00-08:00"), "--occupied");
  testing::expect_input_error(run_relight(base + "'" + room.epw.string() + "' --sensors ceiling"),
                              "--sensors: the scene has no sensor set \"ceiling\"");
  std::string text = read_text(room.epw);
  text.replace(text.find("\n2023,3,2,"), 10, "\n2023,3,x,");
  const fs::path bad = room.dir.write("bad.epw", text);
  testing::expect_input_error(run_relight(base + "'" + bad.string() + "'"),
                              bad.string() + ":33: field 3 (day)");
  testing::expect_input_error(
      run_relight(base + "'" + (room.dir.path() / "none.epw").string() + "'"),
      (room.dir.path() / "none.epw").string());
  // Night only: nothing to evaluate.
  testing::expect_input_error(
      run_relight(base + "'" + room.epw.string() + "' --occupied 00:00-02:00"),
      room.epw.string() + ": no occupied hour has the sun up");
}

// RELIGHT_THREADS caps relight's parallel loops (cli/cli.cpp): one thread makes one stream of
// hours, and the values do not change; a bad value is an input error naming the variable.
TEST(AnnualCommand, RelightThreadsCapsTheStreamsAndKeepsTheValues) {
  const AnnualRoom& room = annual_room();
  const std::string args = "annual '" + room.rlt.string() + "' --weather '" + room.epw.string() +
                           "' --occupied 11:00-13:00 -o '";
  const fs::path all = room.dir.path() / "all-threads.csv", one = room.dir.path() / "one.csv";
  const auto every_core = run_relight(args + all.string() + "'");
  ASSERT_EQ(every_core.exit_code, 0) << every_core.err;
  const auto capped = run_relight(args + one.string() + "'", "export RELIGHT_THREADS=1");
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  EXPECT_NE(capped.out.find(" in 1 streams"), std::string::npos) << capped.out;
  EXPECT_EQ(read_text(one), read_text(all));
  for (const char* bad : {"0", "two", "-1", "3x", "''", "99999"}) {
    testing::expect_input_error(
        run_relight(args + one.string() + "'", std::string("export RELIGHT_THREADS=") + bad),
        "RELIGHT_THREADS: expected a whole number");
  }
}

}  // namespace
}  // namespace relight
