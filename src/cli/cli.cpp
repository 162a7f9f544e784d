#include "cli/cli.h"

#include <exception>
#include <iostream>
#include <new>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/input_error.h"

namespace relight {

int run_cli(int argc, char** argv) {
  CLI::App app{"relight: interactive lighting design by precomputed radiance transfer", "relight"};
  app.require_subcommand(1, 1);
  Action action;
  add_reference_command(app, action);
  add_info_command(app, action);
  add_precompute_command(app, action);
  add_render_command(app, action);
  add_probe_command(app, action);
  add_annual_command(app, action);
  add_glare_command(app, action);
  add_report_command(app, action);
  add_bench_command(app, action);
  add_analyze_command(app, action);
  add_serve_command(app, action);
  add_nearfield_command(app, action);
  add_capture_command(app, action);
  add_optimize_command(app, action);
  add_demo_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::string where = "relight";
    for (const CLI::App* sub : app.get_subcommands()) where += " " + sub->get_name();
    std::cerr << "error: " << where << ": " << e.what() << "\n";
    return 2;
  }
  try {
    return action();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: internal: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: internal: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace relight
