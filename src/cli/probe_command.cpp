// `relight probe SCENE.rlt [--state STATE.json] [-o SENSORS.csv]`: sensor illuminance of
// the precomputed scene under a lighting state, in the reference's CSV format, with
// Eavg, Emin, Emax and U0 per sensor set on stdout.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/input_error.h"
#include "render/sensor_report.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

struct ProbeArgs {
  std::string rlt, state, output;
};

int run_probe(const ProbeArgs& args) {
  const RelitScene relit(args.rlt, args.state.empty()
                                       ? std::nullopt
                                       : std::optional<std::filesystem::path>(args.state));
  const Scene& scene = relit.scene();
  if (scene.sensor_count() == 0) fail_input(args.rlt, "the scene has no sensors");
  const std::vector<Rgb> e = relit.sensor_irradiance();
  print_sensor_statistics(std::cout, sensor_statistics(scene, e));
  if (!args.output.empty()) {
    write_sensor_csv(args.output, scene, e);
    std::cout << "wrote " << args.output << "\n";
  }
  return 0;
}

}  // namespace

void add_probe_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* cmd = app.add_subcommand("probe", "Sensor illuminance of a precomputed scene");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  cmd->add_option("-o,--output", args->output, "sensor CSV to write");
  cmd->callback([args, &action] { action = [args] { return run_probe(*args); }; });
}

}  // namespace relight
