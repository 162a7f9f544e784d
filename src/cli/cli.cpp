#include "cli/cli.h"

#include <charconv>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string_view>

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "common/input_error.h"

namespace relight {

namespace {

// RELIGHT_THREADS, when set: the most threads relight's parallel loops use (oneTBB's
// max_allowed_parallelism; unset, every core). For a shared machine, and for ThreadSanitizer
// runs of the studio server (scripts/test-sanitize.sh), which cannot see the synchronisation
// inside Debian's uninstrumented oneTBB. A whole number from 1 to 4096; anything else is an
// input error (exit 2). Pinned by tests/cli/annual_command_test.cpp.
std::optional<std::size_t> thread_limit() {
  const char* text = std::getenv("RELIGHT_THREADS");
  if (text == nullptr) return std::nullopt;
  const std::string_view value(text);
  std::size_t threads = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), threads);
  if (error != std::errc() || end != value.data() + value.size() || threads < 1 || threads > 4096) {
    throw InputError("RELIGHT_THREADS: expected a whole number of threads from 1 to 4096, got '" +
                     std::string(value) + "'");
  }
  return threads;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"relight: interactive lighting design by precomputed radiance transfer", "relight"};
  app.require_subcommand(1, 1);
  Action action;
  add_reference_command(app, action);
  add_info_command(app, action);
  add_import_command(app, action);
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
    std::optional<tbb::global_control> limit;
    if (const std::optional<std::size_t> threads = thread_limit()) {
      limit.emplace(tbb::global_control::max_allowed_parallelism, *threads);
    }
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
