// Stored SH transfer in binary16 (scene "precompute": {"storage": "fp16"}) against fp32: every
// value `relight probe` reports within 0.1 % of the fp32 file's (lux and each of r, g, b), on the
// demo room (five luminaires and a window under an overcast sky; under a state with the luminaires
// dimmed, recoloured and re-aimed and the window under a sunny sky) and on a room with a window and
// a skylight; the fp16 file's interreflected transfer takes half the bytes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/demo_room.h"
#include "run_command.h"
#include "store/rlt_file.h"
#include "support/daylight_room.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

// The lux, r, g and b columns of every sensor `probe` reports under `state`.
std::vector<double> probe_values(const TempDir& dir, const fs::path& rlt,
                                 const std::string& state) {
  const fs::path state_file = dir.write("state.json", state);
  const fs::path csv = dir.path() / "probe.csv";
  const testing::CommandResult r = run_relight("probe '" + rlt.string() + "' --state '" +
                                               state_file.string() + "' -o '" + csv.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<double> out;
  const auto rows = parse_csv(read_text(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    for (std::size_t c = 8; c < 12; ++c) out.push_back(std::stod(rows[i].at(c)));
  }
  return out;
}

// Bytes of the sections whose name contains "indirect sh" (luminaires' and portals').
std::uint64_t indirect_bytes(const fs::path& rlt) {
  std::uint64_t bytes = 0;
  const RltFile file = RltFile::open(rlt);
  for (const RltSectionInfo& s : file.sections()) {
    if (s.name.find("indirect sh") != std::string::npos) bytes += s.size;
  }
  return bytes;
}

void expect_fp16_within_a_tenth_of_a_percent(const std::string& name, nlohmann::json scene,
                                             const std::vector<std::string>& states) {
  const TempDir dir;
  scene["precompute"]["storage"] = "fp32";
  const fs::path single = testing::precompute_scene(dir, name + "-fp32", scene.dump(2));
  scene["precompute"]["storage"] = "fp16";
  const fs::path half = testing::precompute_scene(dir, name + "-fp16", scene.dump(2));
  EXPECT_EQ(indirect_bytes(half) * 2, indirect_bytes(single));
  for (const std::string& state : states) {
    const std::vector<double> expected = probe_values(dir, single, state);
    const std::vector<double> got = probe_values(dir, half, state);
    ASSERT_EQ(got.size(), expected.size());
    ASSERT_GE(expected.size(), 40u);
    double worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_GT(expected[i], 0) << i;
      const double off = std::abs(got[i] - expected[i]) / expected[i];
      worst = std::max(worst, off);
      EXPECT_LE(off, 1e-3) << name << " value " << i << ": " << got[i] << " against " << expected[i]
                           << " under " << state;
    }
    std::printf("%s: fp16 against fp32, worst %.4f %% over %zu values under %s\n", name.c_str(),
                100 * worst, expected.size(), state.c_str());
  }
}

TEST(TransferStorage, Fp16ProbesTheDemoRoomWithinATenthOfAPercentOfFp32) {
  expect_fp16_within_a_tenth_of_a_percent("demo", demo_room_scene(), {"{}", R"({ "luminaires": {
                    "downlight left": { "dimmer": 0.3, "cct_kelvin": 2700 },
                    "wall washer": { "color": [0.2, 0.5, 1.0], "aim": [1, -1, 0] },
                    "pendant": { "on": false } },
                  "portals": { "south window": { "environment": {
                    "type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 12000,
                    "sun": { "latitude": 48.14, "longitude": 11.58, "utc_offset": 1,
                             "datetime": "2026-03-21T11:00" },
                    "sun_illuminance": 70000 } } } })"});
}

TEST(TransferStorage, Fp16ProbesAWindowAndSkylightRoomWithinATenthOfAPercentOfFp32) {
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  room.skylight = testing::kSkylight;
  room.albedo = 0.6;
  nlohmann::json scene = testing::window_room_json(room);
  scene["sensors"] = {
      {{"name", "floor"},
       {"grid",
        {{"corner", {0.5, 0.8, 0.5}}, {"u", {3, 0, 0}}, {"v", {0, 0, 4}}, {"nu", 4}, {"nv", 5}}}}};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}};
  expect_fp16_within_a_tenth_of_a_percent("window", scene, {"{}"});
}

}  // namespace
}  // namespace relight
