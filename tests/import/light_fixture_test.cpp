// Light fixtures of a building model (import/imported_scene.h): a fixture becomes a luminaire at
// its placement, aimed down its local −z with C0 along its local x, with the photometric file
// the model names (relative to the model) or the --photometry-map's for its type name; one
// with neither is listed in the warnings by name and type, never dropped silently.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/read_file.h"
#include "import/imported_scene.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

ModelElement slab(std::uint32_t id, double y, bool facing_up) {
  ModelElement e;
  e.id = id;
  e.ifc_class = "IFCSLAB";
  ModelPart part;
  part.positions = {{0, y, 0}, {4, y, 0}, {4, y, 5}, {0, y, 5}};
  part.triangles = facing_up ? std::vector<Triangle>{{0, 2, 1}, {0, 3, 2}}
                             : std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}};
  e.parts.push_back(part);
  return e;
}

ModelElement fixture(std::uint32_t id, const std::string& name, const std::string& type,
                     const std::string& photometry, Vec3 origin) {
  ModelElement e;
  e.id = id;
  e.ifc_class = "IFCLIGHTFIXTURE";
  e.light_fixture = true;
  e.name = name;
  e.type_name = type;
  e.photometry = photometry;
  e.origin = origin;
  e.x_axis = {0, 0, 1};  // C0 along the room's length
  e.z_axis = {0, 1, 0};  // hung from the ceiling: its local z up, light down
  return e;
}

TEST(LightFixture, BecomesALuminaireWithTheModelsOrTheMapsPhotometryElseAWarning) {
  const testing::TempDir dir;
  const fs::path photometry = fs::path(RELIGHT_TEST_DATA) / "photometry";
  fs::copy_file(photometry / "bilateral_90_270_2019.ies", dir.path() / "downlight.ies");
  BuildingModel model;
  model.format = "IFC4";
  model.elements = {slab(1, 0, true), slab(2, 3, false),
                    fixture(10, "DL-1", "Downlight", "downlight.ies", {1, 2.9, 1}),
                    fixture(11, "P-1", "Panel 600", "", {2, 2.9, 3}),
                    fixture(12, "X-1", "Unknown type", "", {3, 2.9, 4})};
  ImportOptions options;
  options.photometry["Panel 600"] = photometry / "small_axial.ldt";
  const fs::path scene_file = dir.path() / "scene" / "house.json";
  fs::create_directories(scene_file.parent_path());
  const ImportSummary summary =
      write_imported_scene(model, options, dir.path() / "house.ifc", scene_file);

  EXPECT_EQ(summary.luminaires, 2);
  const nlohmann::json scene = nlohmann::json::parse(read_file(scene_file));
  const nlohmann::json& lums = scene.at("luminaires");
  ASSERT_EQ(lums.size(), 2U) << lums.dump();
  EXPECT_EQ(lums[0]["name"], "DL-1");
  EXPECT_EQ(lums[0]["position"], nlohmann::json({1, 2.9, 1}));
  EXPECT_EQ(lums[0]["aim"], nlohmann::json({-0.0, -1, -0.0}));
  EXPECT_EQ(lums[0]["c0"], nlohmann::json({0, 0, 1}));
  EXPECT_EQ(lums[0]["distribution"]["type"], "ies");
  // Relative to the scene's folder, which the scene format resolves it against.
  EXPECT_EQ(lums[0]["distribution"]["file"], "../downlight.ies");
  EXPECT_EQ(lums[1]["name"], "P-1");
  EXPECT_EQ(lums[1]["distribution"]["type"], "ldt");
  EXPECT_TRUE(
      fs::equivalent(scene_file.parent_path() / lums[1]["distribution"]["file"].get<std::string>(),
                     photometry / "small_axial.ldt"));
  bool listed = false;
  for (const std::string& w : summary.warnings) {
    listed = listed ||
             (w.find("X-1") != std::string::npos && w.find("Unknown type") != std::string::npos);
  }
  EXPECT_TRUE(listed) << "the fixture without photometry is named in the warnings";
}

}  // namespace
}  // namespace relight
