// Runs the relight binary as a user would and captures exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "support/temp_dir.h"

namespace relight::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline CommandResult run_relight(const std::string& arguments) {
  TempDir capture;
  const auto out = capture.path() / "stdout", err = capture.path() / "stderr";
  const std::string command = std::string("'") + RELIGHT_BINARY + "' " + arguments + " >'" +
                              out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int status = std::system(command.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

}  // namespace relight::testing
