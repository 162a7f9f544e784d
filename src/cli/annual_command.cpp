// `relight annual SCENE.rlt --weather FILE.epw [--state STATE.json] [--sensors NAME,...]
// [--occupied 08:00-18:00] [-o RESULTS.csv] [--hourly-out HOURLY.csv]`: a year of daylight
// through the precomputed transfer (runtime/annual_daylight.h), climate-based metrics per
// sensor in the CSV and per sensor set on stdout (runtime/daylight_metrics.h).
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "common/progress.h"
#include "render/sensor_report.h"
#include "runtime/annual_daylight.h"
#include "runtime/daylight_metrics.h"

namespace relight {

namespace {

struct AnnualArgs {
  std::string rlt, weather, state, sensors, occupied = "08:00-18:00", output, hourly;
};

// A chosen sensor set and its index in the scene.
struct ChosenSet {
  const SensorSet* set;
  std::size_t index;
};

std::vector<ChosenSet> choose_sets(const Scene& scene, const std::string& names) {
  std::vector<ChosenSet> all;
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) all.push_back({&scene.sensors[k], k});
  if (names.empty()) return all;
  std::vector<ChosenSet> chosen;
  std::stringstream list(names);
  std::string name;
  while (std::getline(list, name, ',')) {
    const auto it = std::find_if(all.begin(), all.end(),
                                 [&](const ChosenSet& c) { return c.set->name == name; });
    if (it == all.end()) {
      std::string known;
      for (const ChosenSet& c : all) {
        known += known.empty() ? "\"" : ", \"";
        known += c.set->name;
        known += '"';
      }
      std::string reason = "the scene has no sensor set \"";
      reason += name;
      reason += "\" (it has ";
      reason += known;
      reason += ')';
      fail_input("--sensors", reason);
    }
    chosen.push_back(*it);
  }
  return chosen;
}

std::string results_csv(const std::vector<ChosenSet>& sets,
                        const std::vector<SensorDaylight>& daylight) {
  std::string csv = "sensor,index,x,y,z,da300,udi_fell_short,udi_useful,udi_exceeded,ase_hours\n";
  char line[256];
  std::size_t column = 0;
  for (const ChosenSet& c : sets) {
    for (std::size_t i = 0; i < c.set->points.size(); ++i, ++column) {
      const Vec3& p = c.set->points[i];
      const SensorDaylight& d = daylight[column];
      std::snprintf(line, sizeof line, ",%zu,%.9g,%.9g,%.9g,%.6f,%.6f,%.6f,%.6f,%d\n", i, p.x, p.y,
                    p.z, d.da300, d.udi_fell_short, d.udi_useful, d.udi_exceeded, d.ase_hours);
      csv += csv_name(c.set->name) + line;
    }
  }
  return csv;
}

std::string hourly_csv(const std::vector<ChosenSet>& sets, std::span<const AnnualHour> hours,
                       const AnnualValues& values) {
  std::string csv = "month,day,hour,sensor,index,lux\n";
  char line[128];
  for (std::size_t h = 0; h < hours.size(); ++h) {
    const WeatherRecord& r = hours[h].record;
    std::size_t column = 0;
    for (const ChosenSet& c : sets) {
      const std::string name = csv_name(c.set->name);
      for (std::size_t i = 0; i < c.set->points.size(); ++i, ++column) {
        std::snprintf(line, sizeof line, "%d,%d,%d,", r.month, r.day, r.hour);
        csv += line + name;
        std::snprintf(line, sizeof line, ",%zu,%.7g\n", i,
                      static_cast<double>(values.lux[h * values.sensors + column]));
        csv += line;
      }
    }
  }
  return csv;
}

int run_annual(const AnnualArgs& args) {
  const auto period = parse_occupied_period(args.occupied);
  if (!period) {
    fail_input("--occupied",
               "expected HH:MM-HH:MM with the end after the start (up to 24:00), "
               "got \"" +
                   args.occupied + "\"");
  }
  const WeatherFile weather = read_epw(args.weather);
  const std::unique_ptr<RelitScene> relit = open_for_annual(args.rlt);
  const Scene& scene = relit->scene();
  if (scene.portals.empty())
    fail_input(args.rlt, "the scene has no windows (portals) for daylight");
  if (scene.sensor_count() == 0) fail_input(args.rlt, "the scene has no sensors");
  const std::vector<ChosenSet> sets = choose_sets(scene, args.sensors);
  std::vector<std::size_t> set_indices;
  set_indices.reserve(sets.size());
  for (const ChosenSet& c : sets) set_indices.push_back(c.index);
  const LightingState base = annual_base_state(
      scene, args.state.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.state));
  const AnnualHours hours = annual_hours(weather, *period, north_deg(base));
  const WeatherLocation& at = weather.location;
  std::printf(
      "weather: %s (%.2f°, %.2f°, UTC%+g h): %zu records, %zu occupied (%s), %zu with the "
      "sun up\n",
      at.city.c_str(), at.latitude_deg, at.longitude_deg, at.time_zone_hours,
      weather.records.size(), hours.occupied, args.occupied.c_str(), hours.hours.size());
  if (hours.hours.empty()) fail_input(args.weather, "no occupied hour has the sun up");

  Progress progress("annual", hours.hours.size());
  const AnnualDaylight year =
      annual_daylight(*relit, base, hours.hours, set_indices, [&] { progress.advance(); });
  progress.finish();
  const AnnualValues& values = year.values;
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const SetDaylight& d = year.per_set[k];
    std::printf(
        "%s: %zu points  sDA300/50%% %.1f%%  ASE1000,250h %.1f%%  mean DA300 %.1f%%  "
        "EN 17037 daylight provision: %s\n",
        sets[k].set->name.c_str(), sets[k].set->points.size(), 100 * d.sda300, 100 * d.ase,
        100 * d.mean_da300, daylight_provision_name(d.en17037));
  }
  const RuntimeScene* runtime = relit->relighter().runtime_scene();
  const double importance = runtime != nullptr ? runtime->sensor_importance_seconds() : 0;
  std::printf(
      "annual: %zu hours x %zu sensors in %.2f s (the sensors' importance %.2f s, once; the "
      "hours %.2f s in %zu streams, whose threads spent %.2f s on shells and %.2f s on sums "
      "and suns)\n",
      hours.hours.size(), values.sensors, importance + values.total_seconds, importance,
      values.total_seconds, values.streams, values.shell_seconds,
      values.hour_seconds - values.shell_seconds);
  if (!args.output.empty()) {
    write_text_atomically(args.output, results_csv(sets, year.per_sensor));
    std::printf("wrote %s\n", args.output.c_str());
  }
  if (!args.hourly.empty()) {
    write_text_atomically(args.hourly, hourly_csv(sets, hours.hours, values));
    std::printf("wrote %s\n", args.hourly.c_str());
  }
  return 0;
}

}  // namespace

void add_annual_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<AnnualArgs>();
  CLI::App* cmd = app.add_subcommand(
      "annual", "A year of daylight from an EnergyPlus weather file: sDA, ASE, UDI per sensor");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--weather", args->weather, "EnergyPlus weather file (.epw)")->required();
  cmd->add_option("--state", args->state,
                  "lighting state JSON (luminaires and emitters it does not name are off)");
  cmd->add_option("--sensors", args->sensors, "sensor sets, comma-separated (default: all)");
  cmd->add_option("--occupied", args->occupied, "occupied period, local standard time")
      ->capture_default_str();
  cmd->add_option("-o,--output", args->output, "per-sensor metrics CSV to write");
  cmd->add_option("--hourly-out", args->hourly, "hourly illuminance CSV to write");
  cmd->callback([args, &action] { action = [args] { return run_annual(*args); }; });
}

}  // namespace relight
