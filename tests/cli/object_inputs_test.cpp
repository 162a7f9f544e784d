// Movable objects' inputs as the commands read them (docs/scene-format.md "Movable objects",
// docs/lighting-state.md "Movable objects"): a bad scene or state exits 2 with one line naming
// the file and the JSON pointer, never a crash; an object placed through a wall is allowed and
// warned about once; a hidden object changes what probe reads.
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::TempDir;

std::string room(const std::string& objects) {
  return R"({
  "materials": { "white": { "albedo": [0.6, 0.6, 0.6] }, "glass": { "albedo": [0, 0, 0], "portal": true } },
  "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "normals": "inward",
                  "material": "white" } ],
  "luminaires": [ { "name": "down", "position": [1.5, 2.4, 1.5],
      "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } } ],
  "sensors": [ { "name": "floor", "points": [[1.5, 0.01, 1.5], [0.3, 0.01, 0.3]] } ],
  "objects": )" +
         objects +
         R"(,
  "precompute": { "max_edge": 0.5, "gather_rays": 32, "sh_order": 4 }
})";
}

const char* kTable = R"([ { "name": "table", "geometry": [
    { "type": "box", "min": [1.0, 0.7, 1.0], "max": [2.0, 0.75, 2.0], "material": "white" } ] } ])";

class ObjectInputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    const fs::path scene = dir_->write("room.json", room(kTable));
    rlt_ = dir_->path() / "room.rlt";
    precompute_ =
        run_relight("precompute '" + scene.string() + "' -o '" + rlt_.string() + "' --no-progress");
  }
  static void TearDownTestSuite() { dir_.reset(); }
  void SetUp() override { ASSERT_EQ(precompute_.exit_code, 0) << precompute_.err; }

  static CommandResult probe(const std::string& name, const std::string& state,
                             const fs::path& csv = {}) {
    const fs::path file = dir_->write(name, state);
    std::string args = "probe '" + rlt_.string() + "' --state '" + file.string() + "'";
    if (!csv.empty()) args += " -o '" + csv.string() + "'";
    return run_relight(args);
  }

  static void expect_error(const CommandResult& r, const std::string& prefix) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << "expected: " << prefix << "\n     got: " << r.err;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
  }

  static void expect_state_error(const std::string& name, const std::string& state,
                                 const std::string& where, const std::string& reason) {
    expect_error(probe(name, state),
                 "error: " + (dir_->path() / name).string() + ":" + where + ": " + reason);
  }

  static void expect_scene_error(const std::string& name, const std::string& objects,
                                 const std::string& where, const std::string& reason) {
    const fs::path scene = dir_->write(name, room(objects));
    expect_error(run_relight("precompute '" + scene.string() + "' -o '" +
                             (dir_->path() / "bad.rlt").string() + "' --no-progress"),
                 "error: " + scene.string() + ":" + where + ": " + reason);
  }

  static std::unique_ptr<TempDir> dir_;
  static fs::path rlt_;
  static CommandResult precompute_;
};

std::unique_ptr<TempDir> ObjectInputs::dir_;
fs::path ObjectInputs::rlt_;
CommandResult ObjectInputs::precompute_;

TEST_F(ObjectInputs, PrecomputeReportsEachObjectsSize) {
  EXPECT_NE(precompute_.out.find("object \"table\": "), std::string::npos) << precompute_.out;
}

TEST_F(ObjectInputs, BadSceneObjectsExitTwoWithTheirJsonPath) {
  expect_scene_error(
      "twice.json",
      R"([ { "name": "a", "geometry": [ { "type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": "white" } ] },
                          { "name": "a", "geometry": [ { "type": "box", "min": [1, 0, 1], "max": [2, 1, 2], "material": "white" } ] } ])",
      "/objects/1/name", "the name \"a\" is already used");
  expect_scene_error("empty.json", R"([ { "name": "a", "geometry": [] } ])", "/objects/0/geometry",
                     "an object needs at least one geometry entry");
  expect_scene_error("none.json", R"([ { "name": "a" } ])", "/objects/0",
                     "missing required key \"geometry\"");
  expect_scene_error(
      "glass.json",
      R"([ { "name": "a", "geometry": [ { "type": "quad", "corner": [0, 1, 0], "u": [1, 0, 0], "v": [0, 0, 1], "material": "glass" } ] } ])",
      "/objects/0/geometry", "an object cannot be window glass");
}

TEST_F(ObjectInputs, BadPlacementsExitTwoWithTheirJsonPath) {
  expect_state_error("unknown.json", R"({"objects": {"sofa": {"visible": false}}})",
                     "/objects/sofa", "no movable object named \"sofa\" in the precomputed scene");
  expect_state_error("words.json", R"({"objects": {"table": {"translate": ["a", 0, 0]}}})",
                     "/objects/table/translate/0", "expected a number");
  expect_state_error("short.json", R"({"objects": {"table": {"translate": [1, 0]}}})",
                     "/objects/table/translate", "expected an array of 3 numbers");
  expect_state_error("turn.json", R"({"objects": {"table": {"rotate_deg": "90"}}})",
                     "/objects/table/rotate_deg", "expected a number");
  expect_state_error("visible.json", R"({"objects": {"table": {"visible": 1}}})",
                     "/objects/table/visible", "expected true or false");
  expect_state_error("key.json", R"({"objects": {"table": {"scale": 2}}})", "/objects/table/scale",
                     "unknown key \"scale\"");
  expect_state_error("list.json", R"({"objects": ["table"]})", "/objects",
                     "expected an object mapping object names to placements");
  expect_state_error("entry.json", R"({"objects": {"table": 3}})", "/objects/table",
                     "expected a placement");
}

TEST_F(ObjectInputs, AnObjectThroughAWallIsAllowedAndWarnedAboutOnce) {
  const CommandResult r =
      probe("wall.json", R"({"objects": {"table": {"translate": [1.2, 0, 0]}}})");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "warning: movable object \"table\" is placed through the room's surfaces\n");
  const CommandResult inside =
      probe("inside.json", R"({"objects": {"table": {"translate": [0.5, 0, 0]}}})");
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_EQ(inside.err, "");
}

TEST_F(ObjectInputs, HidingTheTableBrightensTheFloorUnderIt) {
  const fs::path shown = dir_->path() / "shown.csv", hidden = dir_->path() / "hidden.csv";
  ASSERT_EQ(probe("shown.json", "{}", shown).exit_code, 0);
  ASSERT_EQ(probe("hidden.json", R"({"objects": {"table": {"visible": false}}})", hidden).exit_code,
            0);
  // The floor point under the table's centre: its lux, the csv's 9th column.
  const auto lux_under = [](const fs::path& csv) {
    std::ifstream in(csv);
    std::string header, line;
    std::getline(in, header);
    std::getline(in, line);
    std::size_t at = 0;
    for (int comma = 0; comma < 8; ++comma) at = line.find(',', at) + 1;
    return std::stod(line.substr(at));
  };
  const double under = lux_under(shown), open = lux_under(hidden);
  std::printf("floor under the table: %.2f lx shown, %.2f lx hidden\n", under, open);
  EXPECT_LT(under, 0.3 * open);
}

}  // namespace
}  // namespace relight
