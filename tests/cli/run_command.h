// Runs the relight binary as a user would and captures exit code, stdout and stderr;
// checks of the exit-code contract and a reader for the sensor CSV.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace relight::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs a shell command line with stdin empty; captures exit code, stdout and stderr.
inline CommandResult run_shell(const std::string& command_line) {
  TempDir capture;
  const auto out = capture.path() / "stdout", err = capture.path() / "stderr";
  const std::string command =
      command_line + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int status = std::system(command.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// `shell` runs before the command in the same shell (a ulimit, say).
inline CommandResult run_relight(const std::string& arguments, const std::string& shell = "") {
  return run_shell((shell.empty() ? "" : shell + " && ") + "'" + RELIGHT_BINARY + "' " + arguments);
}

// Writes `scene_json` as NAME.json in `dir` and precomputes it to NAME.rlt (its path).
inline std::filesystem::path precompute_scene(const TempDir& dir, const std::string& name,
                                              const std::string& scene_json) {
  const std::filesystem::path file = dir.write(name + ".json", scene_json);
  const std::filesystem::path rlt = dir.path() / (name + ".rlt");
  const CommandResult r =
      run_relight("precompute '" + file.string() + "' -o '" + rlt.string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return rlt;
}

// Exit 2 and exactly one line on stderr, starting "error: " + prefix.
inline void expect_input_error(const CommandResult& r, const std::string& prefix) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("error: " + prefix, 0), 0u) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
}

// Rows of comma-separated cells (no quoting: the tests' sensor names are plain).
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream l(line);
    for (std::string cell; std::getline(l, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// The `lux` column of a sensor CSV written by `relight probe -o` or `relight reference
// --sensors-out` (docs: sensor,index,x,y,z,nx,ny,nz,lux,r,g,b), one value per sensor point.
inline std::vector<double> sensor_lux(const std::filesystem::path& csv) {
  std::vector<double> out;
  const auto rows = parse_csv(read_text(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) out.push_back(std::stod(rows[i].at(8)));
  return out;
}

}  // namespace relight::testing
