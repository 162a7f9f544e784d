// Runs another program and waits for it: the IFC reader (node) behind `relight import`, and
// the studio's import and precompute of an uploaded model (serve/model_opening.h). Its
// standard output is kept; its standard error is handed over line by line as it arrives
// (progress bars in log form, common/progress.h) and its end kept for error messages.
// Pinned by tests/common/child_process_test.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace relight {

struct ChildOptions {
  // Each line of standard error as it arrives, without its '\n'; may be empty.
  std::function<void(const std::string& line)> on_error_line;
  // Asked about five times a second; true ends the program (SIGTERM) and run_child returns.
  std::function<bool()> cancelled;
};

struct ChildResult {
  int status = -1;      // its exit code, or 128 + the signal that ended it
  std::string out;      // standard output, whole
  std::string err_end;  // the last 64 KiB of standard error
};

// Runs argv[0] (looked up in PATH when it has no '/') with argv, standard input empty.
// Throws std::runtime_error ("cannot run PROGRAM: reason") when it cannot be started.
ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options = {});

// The last non-empty line of `text` (an error message's reason), without surrounding blanks.
std::string last_line(const std::string& text);

}  // namespace relight
