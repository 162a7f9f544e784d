// The subcommands of `relight`. Each add_* registers its options on the parent app
// and sets `action` to the function that runs it after parsing.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace relight {

using Action = std::function<int()>;

void add_reference_command(CLI::App& app, Action& action);
void add_info_command(CLI::App& app, Action& action);
void add_import_command(CLI::App& app, Action& action);
void add_demo_command(CLI::App& app, Action& action);
void add_precompute_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_probe_command(CLI::App& app, Action& action);
void add_annual_command(CLI::App& app, Action& action);
void add_glare_command(CLI::App& app, Action& action);
void add_report_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_analyze_command(CLI::App& app, Action& action);
void add_serve_command(CLI::App& app, Action& action);
void add_nearfield_command(CLI::App& app, Action& action);
void add_capture_command(CLI::App& app, Action& action);
void add_optimize_command(CLI::App& app, Action& action);

}  // namespace relight
