// `relight optimize SCENE.rlt --targets TARGETS.json [--state START.json] [--daylight]
// -o STATE.json`: inverse lighting design (design/optimize.h). Writes the lighting
// state that meets the targets (or comes closest) and prints one JSON line: feasible,
// objective, iterations, seconds, binding, per target the achieved value (docs/optimize.md).
// Exit 0 whether or not the targets are feasible; 2 for bad input.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "design/optimize.h"
#include "scene/json_node.h"

namespace relight {

namespace {

struct OptimizeArgs {
  std::string rlt, targets, state, output;
  bool daylight = false;
};

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

int run_optimize(const OptimizeArgs& args) {
  RelitScene relit(args.rlt, std::nullopt);
  const Scene& scene = relit.scene();
  if (scene.sensor_count() == 0) fail_input(args.rlt, "the scene has no sensors to set targets on");
  const DesignTargets targets = load_design_targets(args.targets, scene);
  StartState start;
  if (!args.state.empty()) {
    start.document = read_json_file(args.state);
    start.dir = folder_of(args.state);
    start.where = args.state;
  }
  OptimizeOptions options;
  options.daylight = args.daylight;
  const OptimizeResult result = optimize_lighting(relit, start, targets, options);
  const nlohmann::json written =
      rebase_relative_files(result.state, start.dir, folder_of(args.output));
  write_text_atomically(args.output, written.dump(2) + "\n");
  std::cout << optimize_summary(scene, result).dump() << std::endl;
  return 0;
}

}  // namespace

void add_optimize_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<OptimizeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "Luminaire dimmers (and aims) that meet illuminance targets at the sensors");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--targets", args->targets, "targets JSON (docs/optimize.md)")->required();
  cmd->add_option("--state", args->state, "start lighting state JSON (default: the scene's own)");
  cmd->add_flag("--daylight", args->daylight,
                "keep the start state's daylight: luminaires top it up (else windows are dark)");
  cmd->add_option("-o,--output", args->output, "lighting state JSON to write")->required();
  cmd->callback([args, &action] { action = [args] { return run_optimize(*args); }; });
}

}  // namespace relight
