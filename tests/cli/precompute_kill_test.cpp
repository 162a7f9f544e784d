// Crash safety: `relight precompute` killed with SIGKILL at 20 moments spread over a whole
// run — tracing, solving, writing, renaming — never leaves a partial or corrupt .rlt at the output
// path: the earlier file there stays byte for byte, or the run had finished and its new file is
// whole (it opens and validates).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "run_command.h"
#include "store/rlt_file.h"

extern char** environ;

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::TempDir;

// A grey room with a downlight; `gather_rays` sets how long its precompute runs.
std::string room(int gather_rays, double max_edge) {
  return R"({
  "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] } },
  "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [4, 2.5, 4], "normals": "inward",
                  "material": "grey" },
                { "type": "box", "min": [1, 0, 1], "max": [2, 0.8, 2], "material": "grey" } ],
  "luminaires": [ { "name": "down", "position": [2, 2.4, 2],
      "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } } ],
  "sensors": [ { "name": "floor", "grid": { "corner": [0.5, 0, 0.5], "u": [3, 0, 0],
                                            "v": [0, 0, 3], "nu": 4, "nv": 4 } } ],
  "precompute": { "max_edge": )" +
         std::to_string(max_edge) + R"(, "gather_rays": )" + std::to_string(gather_rays) +
         R"( }
})";
}

// Starts `relight precompute SCENE -o OUT` with its output discarded; returns its pid.
pid_t start_precompute(const fs::path& scene, const fs::path& out) {
  const std::string binary = RELIGHT_BINARY;
  std::vector<std::string> args{binary, "precompute", scene.string(),
                                "-o",   out.string(), "--no-progress"};
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

bool opens_whole(const fs::path& file) {
  try {
    RltFile::open(file);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

TEST(PrecomputeKill, SigkillAtTwentyMomentsLeavesTheEarlierFileOrAWholeNewOne) {
  TempDir dir;
  const fs::path earlier_scene = dir.write("earlier.json", room(8, 1.0));
  const fs::path scene = dir.write("room.json", room(256, 0.2));
  const fs::path out = dir.path() / "room.rlt", saved = dir.path() / "earlier.rlt";
  // The earlier file, and how long a whole run of the heavier scene takes.
  ASSERT_EQ(testing::run_relight("precompute '" + earlier_scene.string() + "' -o '" +
                                 saved.string() + "' --no-progress")
                .exit_code,
            0);
  const std::string earlier = read_text(saved);
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(testing::run_relight("precompute '" + scene.string() + "' -o '" +
                                 (dir.path() / "whole.rlt").string() + "' --no-progress")
                .exit_code,
            0);
  const double whole =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int kept = 0, replaced = 0;
  for (int i = 0; i < 20; ++i) {
    fs::copy_file(saved, out, fs::copy_options::overwrite_existing);
    // Moments spread over the run and a little past it (the write and the rename come last).
    const double at = whole * 1.1 * (i + 0.5) / 20;
    const pid_t pid = start_precompute(scene, out);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(fs::exists(out)) << "killed at " << at << " s";
    if (read_text(out) == earlier) {
      ++kept;
    } else {
      EXPECT_TRUE(opens_whole(out)) << "killed at " << at << " s: a partial or corrupt file";
      ++replaced;
    }
  }
  // What a killed run cannot clean up: its temporary beside the output (reported).
  int temporaries = 0;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    if (name != "earlier.json" && name != "room.json" && name != "room.rlt" &&
        name != "earlier.rlt" && name != "whole.rlt") {
      ++temporaries;
    }
  }
  std::printf(
      "whole run %.2f s; 20 kills: earlier file kept %d times, whole new file %d; %d "
      "temporaries left beside the output\n",
      whole, kept, replaced, temporaries);
  EXPECT_GT(kept, 0);  // the kills did land during the run
}

}  // namespace
}  // namespace relight
