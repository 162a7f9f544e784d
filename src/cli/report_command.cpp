// `relight report SCENE.rlt [--state STATE.json] [--weather FILE.epw] -o REPORT.html`: the
// designer's report (render/report.h), with a year of daylight (runtime/annual_daylight.h,
// occupied 08:00–18:00) when a weather file is given; written atomically.
#include <cstdio>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "common/progress.h"
#include "render/report.h"
#include "runtime/annual_daylight.h"

namespace relight {

namespace {

struct ReportArgs {
  std::string rlt, state, weather, output;
};

std::optional<std::filesystem::path> state_path(const std::string& state) {
  return state.empty() ? std::nullopt : std::optional<std::filesystem::path>(state);
}

AnnualReport year_of_daylight(const ReportArgs& args) {
  const WeatherFile weather = read_epw(args.weather);
  const std::unique_ptr<RelitScene> relit = open_for_annual(args.rlt);
  const Scene& scene = relit->scene();
  const LightingState base = annual_base_state(scene, state_path(args.state));
  const AnnualHours hours = annual_hours(weather, OccupiedPeriod{}, north_deg(base));
  if (hours.hours.empty()) fail_input(args.weather, "no occupied hour has the sun up");
  Progress progress("annual", hours.hours.size());
  AnnualDaylight year = annual_daylight(*relit, base, hours.hours, every_sensor_set(scene),
                                        [&] { progress.advance(); });
  progress.finish();
  AnnualReport out;
  char heading[256];
  std::snprintf(heading, sizeof heading,
                "%s (%.2f°, %.2f°, UTC%+g h): %zu occupied hours (08:00–18:00, local standard "
                "time) with the sun up, daylight alone unless the state names luminaires.",
                weather.location.city.c_str(), weather.location.latitude_deg,
                weather.location.longitude_deg, weather.location.time_zone_hours,
                hours.hours.size());
  out.weather = heading;
  out.per_sensor = std::move(year.per_sensor);
  out.per_set = std::move(year.per_set);
  return out;
}

int run_report(const ReportArgs& args) {
  RelitScene relit(args.rlt, state_path(args.state));
  if (relit.scene().sensor_count() == 0) fail_input(args.rlt, "the scene has no sensors");
  ReportOptions options;
  options.title = std::filesystem::path(args.rlt).filename().string();
  options.state = args.state;
  if (!args.weather.empty()) {
    if (relit.scene().portals.empty()) {
      fail_input(args.rlt, "the scene has no windows (portals) for daylight");
    }
    options.annual = year_of_daylight(args);
  }
  write_text_atomically(args.output, report_html(relit, options));
  std::printf("wrote %s\n", args.output.c_str());
  return 0;
}

}  // namespace

void add_report_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand("report", "A self-contained HTML report of a lit scene");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  cmd->add_option("--weather", args->weather, "EnergyPlus weather file: add a year of daylight");
  cmd->add_option("-o,--output", args->output, "HTML file to write")->required();
  cmd->callback([args, &action] { action = [args] { return run_report(*args); }; });
}

}  // namespace relight
