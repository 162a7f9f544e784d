// Entry point of the `relight` command line: subcommands, argument parsing and the
// exit-code contract (0 success, 2 bad input with "error: WHERE: reason", 1 internal).
#pragma once

namespace relight {

int run_cli(int argc, char** argv);

}  // namespace relight
