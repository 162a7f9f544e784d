// `relight nearfield` as a user runs it: one JSON line with the contract's keys for each method;
// moving an emitter through the state changes the samples and the image and leaves the .rlt as it
// was (no new precompute); emitters in scene and state are validated with their JSON paths; a scene
// without emitters is bad input.
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::expect_input_error;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

const char* kRoom = R"({
  "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] } },
  "geometry": [
    { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward", "material": "grey" },
    { "type": "box", "min": [1.2, 0, 1.2], "max": [1.8, 0.6, 1.8], "material": "grey" } ],
  "emitters": [
    { "name": "orb", "geometry": { "type": "sphere", "center": [0.8, 1.6, 0.8], "radius": 0.15,
                                   "subdivisions": 2 }, "luminance": 3000, "color": [1, 0.8, 0.6] } ],
  "cameras": [ { "name": "in", "eye": [1.5, 1.5, 2.9], "target": [1.5, 0.5, 1.5] } ],
  "precompute": { "max_edge": 0.5, "gather_rays": 16, "nearfield_directions": 64 }
})";

class NearfieldCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    const fs::path scene = dir_->write("room.json", kRoom);
    const auto r = run_relight("precompute '" + scene.string() + "' -o '" + rlt().string() +
                               "' --no-progress");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { dir_.reset(); }
  static fs::path rlt() { return dir_->path() / "room.rlt"; }
  static std::unique_ptr<TempDir> dir_;  // one precompute for the suite
};
std::unique_ptr<TempDir> NearfieldCommand::dir_;

nlohmann::json json_line(const std::string& out) {
  EXPECT_EQ(out.find('\n'), out.size() - 1) << out;
  return nlohmann::json::parse(out);
}

TEST_F(NearfieldCommand, OneJsonLinePerMethodWithTheContractKeys) {
  for (const char* method : {"adaptive", "icp", "truth"}) {
    const auto r = run_relight("nearfield '" + rlt().string() +
                               "' --epsilon 5 --max-samples 32 "
                               "--face-size 8 --method " +
                               method);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = json_line(r.out);
    for (const char* key :
         {"method", "epsilon", "max_samples", "receivers", "samples", "evaluations", "placement_s",
          "sampling_s", "reconstruction_s", "truth_s", "rmse", "rmse_relative"}) {
      EXPECT_TRUE(j.contains(key)) << method << " " << key;
    }
    EXPECT_EQ(j["method"], method);
    EXPECT_GE(j["samples"].get<int>(), 1);
    if (std::string(method) == "truth") {
      EXPECT_EQ(j["samples"], j["receivers"]);
      EXPECT_EQ(j["rmse"], 0.0);
    } else {
      EXPECT_LE(j["samples"].get<int>(), 32);
      EXPECT_GT(j["rmse"].get<double>(), 0.0);
      EXPECT_LT(j["rmse_relative"].get<double>(), 1.0);
    }
  }
}

TEST_F(NearfieldCommand, MovingAnEmitterChangesSamplesAndImageWithoutPrecompute) {
  const std::string before = read_text(rlt());
  const fs::path still = dir_->write("still.json", "{}");
  const fs::path moved = dir_->write(
      "moved.json", R"({"emitters": {"orb": {"translate": [1.4, -0.7, 1.4], "rotate_deg": 30}}})");
  const auto run = [&](const fs::path& state, const std::string& image) {
    const auto r = run_relight("nearfield '" + rlt().string() + "' --state '" + state.string() +
                               "' --epsilon 50 --max-samples 4096 --face-size 8 --width 48 "
                               "--height 32 -o '" +
                               (dir_->path() / image).string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json_line(r.out);
  };
  const nlohmann::json a = run(still, "still.png"), b = run(moved, "moved.png");
  EXPECT_NE(a["samples"], b["samples"]);
  EXPECT_NE(read_text(dir_->path() / "still.png"), read_text(dir_->path() / "moved.png"));
  EXPECT_EQ(read_text(rlt()), before);
  // Switched off: nothing lights the room, one sample suffices.
  const fs::path off = dir_->write("off.json", R"({"emitters": {"orb": {"on": false}}})");
  EXPECT_EQ(run(off, "off.png")["samples"], 1);
}

TEST_F(NearfieldCommand, BadInputNamesWhere) {
  const fs::path state = dir_->write("bad.json", R"({"emitters": {"lamp": {"on": true}}})");
  expect_input_error(
      run_relight("nearfield '" + rlt().string() + "' --state '" + state.string() + "'"),
      state.string() + ":/emitters/lamp: no emitter named \"lamp\"");
  const fs::path key = dir_->write("key.json", R"({"emitters": {"orb": {"luminance": -1}}})");
  expect_input_error(
      run_relight("nearfield '" + rlt().string() + "' --state '" + key.string() + "'"),
      key.string() + ":/emitters/orb/luminance");
  nlohmann::json scene = nlohmann::json::parse(kRoom);
  scene["emitters"][0].erase("luminance");
  const fs::path broken = dir_->write("broken.json", scene.dump());
  expect_input_error(run_relight("precompute '" + broken.string() + "' -o '" +
                                 (dir_->path() / "x.rlt").string() + "'"),
                     broken.string() + ":/emitters/0");
  scene = nlohmann::json::parse(kRoom);
  scene.erase("emitters");
  const fs::path plain = dir_->write("plain.json", scene.dump());
  const fs::path plain_rlt = dir_->path() / "plain.rlt";
  ASSERT_EQ(run_relight("precompute '" + plain.string() + "' -o '" + plain_rlt.string() +
                        "' --no-progress")
                .exit_code,
            0);
  expect_input_error(run_relight("nearfield '" + plain_rlt.string() + "'"),
                     plain_rlt.string() + ": the scene has no emitters");
}

}  // namespace
}  // namespace relight
