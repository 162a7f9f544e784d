// IFC read through web-ifc (import/ifc_model.h) on the real models of ../shared/data/ifc (skipped
// without them or without node and web-ifc): every window with its glazing, every space, the
// storeys by elevation and the site; a file that is not IFC or is cut short is refused before
// node starts.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "import/ifc_model.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

const fs::path kIfc = fs::path(RELIGHT_SHARED_DIR) / "data" / "ifc";

bool reader_installed() {
  return fs::exists(importer_folder() / "node_modules" / "web-ifc") &&
         std::system("node --version >/dev/null 2>&1") == 0;
}

int count(const BuildingModel& m, const std::string& ifc_class, bool with_glass = false) {
  return static_cast<int>(
      std::count_if(m.elements.begin(), m.elements.end(), [&](const ModelElement& e) {
        return e.ifc_class == ifc_class &&
               (!with_glass || std::any_of(e.parts.begin(), e.parts.end(),
                                           [](const ModelPart& p) { return p.transparent; }));
      }));
}

TEST(IfcModel, TheFzkHausHasItsElevenGlazedWindowsSevenSpacesTwoStoreysAndItsSite) {
  if (!fs::exists(kIfc / "AC20-FZK-Haus.ifc") || !reader_installed())
    GTEST_SKIP() << "no model or reader";
  const BuildingModel m = read_ifc_model(kIfc / "AC20-FZK-Haus.ifc");
  EXPECT_EQ(m.format, "IFC4");
  EXPECT_EQ(count(m, "IFCWINDOW", true), 11);
  EXPECT_EQ(count(m, "IFCSPACE"), 7);
  ASSERT_EQ(m.storeys.size(), 2u);
  EXPECT_EQ(m.storeys[0].name, "Erdgeschoss");
  EXPECT_NEAR(m.storeys[0].elevation, 0, 1e-9);
  EXPECT_NEAR(m.storeys[1].elevation, 2.7, 1e-9);
  ASSERT_TRUE(m.site.has_value());
  EXPECT_NEAR(m.site->latitude, 49.1004, 1e-3);
  EXPECT_NEAR(m.site->longitude, 8.4365, 1e-3);
  EXPECT_NEAR(m.site->elevation_m, 110, 1e-6);
  EXPECT_NEAR(m.site->north_deg, 50, 1e-6);
  // The house stands on the ground: y up, every wall between the slab and the ridge.
  for (const ModelElement& e : m.elements) {
    if (e.ifc_class != "IFCWALLSTANDARDCASE") continue;
    for (const ModelPart& p : e.parts)
      for (const Vec3& v : p.positions) EXPECT_GT(v.y, -1.0);
  }
}

TEST(IfcModel, TheRevitOfficeHasAtLeast95PercentOfItsWindowsAndSpaces) {
  if (!fs::exists(kIfc / "Office_A_20110811.ifc") || !reader_installed())
    GTEST_SKIP() << "no model or reader";
  const BuildingModel m = read_ifc_model(kIfc / "Office_A_20110811.ifc");
  EXPECT_EQ(m.format, "IFC2X3");
  EXPECT_GE(count(m, "IFCWINDOW", true), 66);  // of 69
  EXPECT_GE(count(m, "IFCSPACE"), 95);         // of 99
  EXPECT_EQ(m.storeys.size(), 3u);
}

TEST(IfcModel, AWindowBuiltOfPartsKeepsItsGlazing) {
  if (!fs::exists(kIfc / "IfcOpenHouse_IFC4.ifc") || !reader_installed())
    GTEST_SKIP() << "no model or reader";
  const BuildingModel m = read_ifc_model(kIfc / "IfcOpenHouse_IFC4.ifc");
  EXPECT_EQ(count(m, "IFCWINDOW", true), 5);
}

TEST(IfcModel, AFileThatIsNotIfcOrIsCutShortIsRefusedWithItsReason) {
  testing::TempDir dir;
  const fs::path text = dir.write("notes.ifc", "these are not the droids\n");
  const fs::path empty = dir.write("empty.ifc", "");
  const fs::path cut = dir.write(
      "cut.ifc", "ISO-10303-21;\nHEADER;\nFILE_SCHEMA(('IFC4'));\nENDSEC;\nDATA;\n#1=IFCPROJECT(");
  const auto message = [](const fs::path& f) {
    try {
      read_ifc_model(f);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(text),
            text.string() + ": not an IFC file: it does not begin with ISO-10303-21;");
  EXPECT_EQ(message(empty),
            empty.string() + ": not an IFC file: it does not begin with ISO-10303-21;");
  EXPECT_EQ(message(cut),
            cut.string() + ": truncated: the IFC file does not end with END-ISO-10303-21;");
  EXPECT_EQ(message(dir.path() / "missing.ifc"),
            (dir.path() / "missing.ifc").string() + ": cannot open it");
}

}  // namespace
}  // namespace relight
