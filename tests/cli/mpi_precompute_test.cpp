// `mpirun -n 2 relight precompute` writes the file one process writes, byte for byte, and probe
// reads the same light from it: on the demo room (luminaires and a window) and on a room with two
// windows, a luminaire, a near-field emitter and a movable object (every per-receiver phase the
// ranks split: gather rays, direct visibility, portal cubemaps, near-field transfer). Two ranks on
// this machine's cores, oversubscribed on loopback (as root where CI runs as root). A failure
// before the ranks exchange anything is reported once, exit 2.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <string>

#include <gtest/gtest.h>

#include "cli/demo_room.h"
#include "run_command.h"
#include "store/rlt_file.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

// The launcher for two ranks; the shell command runs relight under it. Under AddressSanitizer
// (make test-sanitize) the ranks unwind malloc's stacks fully, so that Open MPI's own leaks at
// MPI_Init match tests/sanitize/lsan-suppressions.txt.
std::string mpirun_two() {
  const char* sanitizer = std::getenv("RELIGHT_SANITIZER");
  std::string launcher = sanitizer != nullptr && std::string(sanitizer) == "address"
                             ? "ASAN_OPTIONS=\"$ASAN_OPTIONS:fast_unwind_on_malloc=0\" "
                             : "";
  launcher += "mpirun -n 2 --oversubscribe";
  if (::geteuid() == 0) launcher += " --allow-run-as-root";
  return launcher;
}

constexpr std::uint32_t kMetadata = rlt_fourcc("META");

// The same sections in the same order, every one byte for byte but the metadata, which differs
// only in the phases' times.
void expect_same_transfer(const fs::path& one, const fs::path& two) {
  const RltFile a = RltFile::open(one), b = RltFile::open(two);
  ASSERT_EQ(a.sections().size(), b.sections().size());
  for (std::size_t i = 0; i < a.sections().size(); ++i) {
    const RltSectionInfo &x = a.sections()[i], &y = b.sections()[i];
    ASSERT_EQ(x.type, y.type) << i;
    ASSERT_EQ(x.name, y.name) << i;
    if (x.type == kMetadata) continue;
    ASSERT_EQ(x.size, y.size) << x.name;
    const std::span<const std::byte> p = a.section(x.type), q = b.section(y.type);
    EXPECT_TRUE(std::equal(p.begin(), p.end(), q.begin())) << x.name << " differs";
  }
  nlohmann::json m = nlohmann::json::parse(a.text(kMetadata));
  nlohmann::json n = nlohmann::json::parse(b.text(kMetadata));
  ASSERT_TRUE(m.contains("phases"));
  m.erase("phases");
  n.erase("phases");
  EXPECT_EQ(m, n);
}

// Precomputes `scene` alone and on two ranks; expects equal files and equal probes.
void expect_two_ranks_write_what_one_writes(const TempDir& dir, const std::string& name,
                                            const nlohmann::json& scene) {
  const fs::path file = dir.write(name + ".json", scene.dump(2));
  const fs::path one = dir.path() / (name + "-one.rlt"), two = dir.path() / (name + "-two.rlt");
  const testing::CommandResult alone =
      run_relight("precompute '" + file.string() + "' -o '" + one.string() + "' --no-progress");
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const std::string command = mpirun_two() + " '" + RELIGHT_BINARY + "' precompute '" +
                              file.string() + "' -o '" + two.string() + "' --no-progress";
  const testing::CommandResult ranks = testing::run_shell(command);
  ASSERT_EQ(ranks.exit_code, 0) << ranks.err;
  EXPECT_NE(ranks.out.find("2 ranks"), std::string::npos) << ranks.out;
  EXPECT_EQ(ranks.out.find("precompute "), ranks.out.rfind("precompute ")) << "printed twice";
  // A rank's predicted peak against the most a rank held (sources/precompute_memory.h).
  const std::size_t peak = ranks.out.find("peak resident memory: ");
  const std::size_t estimate = ranks.out.find("memory estimate: ");
  ASSERT_NE(peak, std::string::npos) << ranks.out;
  ASSERT_NE(estimate, std::string::npos) << ranks.out;
  const std::size_t most = ranks.out.find("–", peak);  // "least–most MB a rank"
  ASSERT_NE(most, std::string::npos) << ranks.out;
  const double most_mb = std::strtod(ranks.out.c_str() + most + std::string("–").size(), nullptr);
  const double estimate_mb =
      std::strtod(ranks.out.c_str() + estimate + std::string("memory estimate: ").size(), nullptr);
  if (std::getenv("RELIGHT_SANITIZER") == nullptr) {
    EXPECT_NEAR(estimate_mb / most_mb, 1, 0.25) << ranks.out;
  }
  expect_same_transfer(one, two);
  const fs::path csv_one = dir.path() / (name + "-one.csv"),
                 csv_two = dir.path() / (name + "-two.csv");
  ASSERT_EQ(run_relight("probe '" + one.string() + "' -o '" + csv_one.string() + "'").exit_code, 0);
  ASSERT_EQ(run_relight("probe '" + two.string() + "' -o '" + csv_two.string() + "'").exit_code, 0);
  EXPECT_EQ(read_text(csv_two), read_text(csv_one));
  EXPECT_GT(read_text(csv_one).size(), 100u);
}

TEST(MpiPrecompute, TwoRanksWriteTheDemoRoomByteForByteAsOneProcess) {
  const TempDir dir;
  expect_two_ranks_write_what_one_writes(dir, "demo", demo_room_scene());
}

TEST(MpiPrecompute, TwoRanksWriteAWindowRoomWithEverySourceByteForByteAsOneProcess) {
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  room.skylight = testing::kSkylight;
  room.albedo = 0.5;
  nlohmann::json scene = testing::window_room_json(room);
  scene["sensors"] = {
      {{"name", "floor"},
       {"grid",
        {{"corner", {0.5, 0.8, 0.5}}, {"u", {3, 0, 0}}, {"v", {0, 0, 4}}, {"nu", 6}, {"nv", 8}}}}};
  scene["luminaires"] = {testing::panel_luminaire("panel")};
  testing::add_strip_and_cabinet(scene);
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}};
  const TempDir dir;
  expect_two_ranks_write_what_one_writes(dir, "window", scene);
}

TEST(MpiPrecompute, AMissingSceneIsReportedOnceWithExitTwo) {
  const TempDir dir;
  const testing::CommandResult r = testing::run_shell(
      mpirun_two() + " '" + RELIGHT_BINARY + "' precompute '" + (dir.path() / "no.json").string() +
      "' -o '" + (dir.path() / "no.rlt").string() + "' --no-progress");
  EXPECT_NE(r.exit_code, 0);
  const std::string first = r.err.substr(0, r.err.find('\n'));
  EXPECT_EQ(first.rfind("error: ", 0), 0u) << r.err;
  EXPECT_NE(first.find("no.json"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("no.json", r.err.find('\n')), std::string::npos)
      << "reported twice: " << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "no.rlt"));
}

// 300 × 300 work-plane sensors under 400 luminaires of sh_order 32: 90,000 receivers × 409,600
// bounced columns, over a terabyte at the precompute's peak — more than any machine this runs
// on has.
nlohmann::json too_large_scene() {
  testing::WindowRoom room;
  room.albedo = 0.5;
  nlohmann::json scene = testing::window_room_json(room);
  scene["portals"] = nlohmann::json::array();
  scene["sensors"] = {{{"name", "work plane"},
                       {"grid",
                        {{"corner", {0.1, 0.8, 0.1}},
                         {"u", {3.8, 0, 0}},
                         {"v", {0, 0, 4.8}},
                         {"nu", 300},
                         {"nv", 300}}}}};
  scene["luminaires"] = nlohmann::json::array();
  for (int i = 0; i < 400; ++i) {
    nlohmann::json l = testing::panel_luminaire(std::to_string(i));
    l["position"] = {0.5 + 0.15 * (i % 20), 2.9, 0.5 + 0.2 * (i / 20)};
    scene["luminaires"].push_back(l);
  }
  scene["precompute"] = {{"sh_order", 32}};
  return scene;
}

TEST(MpiPrecompute, ASceneTooLargeForARanksShareOfMemoryIsRefusedBeforeTracingWithTheNumbers) {
  const TempDir dir;
  const fs::path file = dir.write("huge.json", too_large_scene().dump());
  const fs::path out = dir.path() / "huge.rlt";
  for (const bool ranks : {false, true}) {
    const auto start = std::chrono::steady_clock::now();
    const std::string command = (ranks ? mpirun_two() + " " : std::string()) + "'" +
                                RELIGHT_BINARY + "' precompute '" + file.string() + "' -o '" +
                                out.string() + "' --no-progress";
    const testing::CommandResult r = testing::run_shell(command);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const std::string first = r.err.substr(0, r.err.find('\n'));
    EXPECT_EQ(first.rfind("error: " + file.string() + ": too large to precompute here", 0), 0u)
        << r.err;
    EXPECT_NE(first.find(" receivers need an estimated "), std::string::npos) << first;
    EXPECT_NE(first.find("409600 basis columns × "), std::string::npos) << first;
    if (ranks) {
      EXPECT_NE(first.find(", shared by its 2 ranks)"), std::string::npos) << first;
      EXPECT_EQ(r.err.find("too large", first.size()), std::string::npos) << "twice: " << r.err;
    } else {
      EXPECT_EQ(r.err, first + "\n");
    }
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out));
    // Refused once the Embree scene is built and a sample of the gather operator's rows traced.
    // Under AddressSanitizer the ranks unwind every allocation's stack (mpirun_two), several
    // times slower: the bound is for the build that ships.
    if (std::getenv("RELIGHT_SANITIZER") == nullptr)
      EXPECT_LT(seconds, 20) << (ranks ? "two ranks" : "one process");
  }
}

// A rank killed outright (SIGKILL) ends the run through the launcher: a non-zero exit, and the
// earlier file at the output path kept as it was.
TEST(MpiPrecompute, ARankKilledEndsTheRunAndLeavesTheEarlierFile) {
  const TempDir dir;
  nlohmann::json scene = demo_room_scene();
  scene["precompute"]["gather_rays"] = 1024;  // long enough to be killed in the middle
  const fs::path file = dir.write("killed.json", scene.dump());
  const fs::path out = dir.write("killed.rlt", "an earlier file");
  const std::string binary = RELIGHT_BINARY;
  // The ranks' command lines start with the binary; mpirun's with "mpirun".
  const std::string command =
      "( " + mpirun_two() + " '" + binary + "' precompute '" + file.string() + "' -o '" +
      out.string() + "' --no-progress & launcher=$!; " + "for i in $(seq 100); do " +
      "[ $(pgrep -f '^" + binary +
      " precompute .*killed' | wc -l) -ge 2 ] && break; sleep 0.1; done; " +
      "sleep 1; pkill -KILL -n -f '^" + binary + " precompute .*killed'; wait $launcher )";
  const testing::CommandResult r = testing::run_shell(command);
  EXPECT_NE(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.err.find("signal 9"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(out), "an earlier file");
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

}  // namespace
}  // namespace relight
