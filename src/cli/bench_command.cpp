// `relight bench`: parses the options, runs benchmark/frame_benchmark.h and prints its line.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "benchmark/edits_benchmark.h"
#include "benchmark/frame_benchmark.h"
#include "cli/commands.h"

namespace relight {

void add_bench_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Time relighting of a precomputed scene");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--frames", args->frames, "frames to time")->check(CLI::Range(1, 100000));
  cmd->add_flag("--sky", args->sky, "change only the sky seen through the portals each frame");
  cmd->add_flag("--environment", args->environment,
                "change only the top-level environment each frame (lit through the cuts)");
  cmd->add_flag("--emitters", args->emitters,
                "move only the near-field emitters each frame (sampling, bounce and sum)");
  cmd->add_flag("--objects", args->objects,
                "move and turn the movable objects each frame (transfer, shadows, bounce)");
  cmd->add_option("--object", args->object, "with --objects: move only this object");
  cmd->add_flag("--materials", args->materials,
                "edit the albedo of the most used material each frame (approximate and final)");
  cmd->add_option("--material", args->material,
                  "with --materials: edit this material (default: the one on the most vertices)");
  cmd->add_flag("--roughness", args->roughness,
                "with --materials: edit the roughness (made glossy first) instead of the albedo");
  cmd->add_flag("--aim", args->aim,
                "turn every luminaire 1 degree about its C0 axis each frame (direct, glossy)");
  cmd->add_flag("--layout", args->layout,
                "move the first luminaire 20 cm and add one each frame (first and converged)");
  cmd->add_option("--optimize", args->optimize,
                  "time relight optimize with these targets (TARGETS.json) against a relight");
  cmd->add_flag("--edits", args->edits,
                "time every kind of edit the scene allows, first and converged frames: one "
                "JSON line per edit, then a summary");
  cmd->callback([args, &action] {
    action = [args] {
      if (args->edits) {
        for (const nlohmann::ordered_json& line : run_edits_bench(*args))
          std::cout << line.dump() << "\n";
      } else {
        std::cout << run_bench(*args).dump() << "\n";
      }
      return 0;
    };
  });
}

}  // namespace relight
