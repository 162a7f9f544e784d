// `relight import` as a user runs it: the FZK-Haus (../shared, skipped without it or without node
// and web-ifc) with its windows as portals, its spaces as sensor sets and its site; one storey of
// it; an OBJ room with a skylight exported with its normals out, found, turned and lit as the
// correctly wound room (its probe within 0.2 %); and bad input refused with exit 2 and its reason.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::expect_input_error;
using testing::run_relight;
using testing::sensor_lux;
using testing::TempDir;

const fs::path kFzk = fs::path(RELIGHT_SHARED_DIR) / "data" / "ifc" / "AC20-FZK-Haus.ifc";

bool ifc_reader_installed() {
  return fs::exists(fs::path(RELIGHT_SOURCE_DIR) / "importer" / "node_modules" / "web-ifc") &&
         std::system("node --version >/dev/null 2>&1") == 0;
}

nlohmann::json read_json(const fs::path& file) {
  return nlohmann::json::parse(testing::read_text(file));
}

TEST(ImportCommand, TheFzkHausBecomesAScenePortalPerGlazingSensorsPerSpaceAndItsSite) {
  if (!fs::exists(kFzk) || !ifc_reader_installed()) GTEST_SKIP() << "no model or IFC reader";
  TempDir dir;
  const fs::path scene = dir.path() / "fzk.json";
  const auto r = run_relight("import '" + kFzk.string() + "' -o '" + scene.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto line = nlohmann::json::parse(r.out);
  EXPECT_EQ(line["storeys"], 2);
  EXPECT_EQ(line["spaces"], 7);
  EXPECT_EQ(line["windows"], 11);
  EXPECT_EQ(line["doors"], 5);
  // The 11 windows and the glazed terrace door.
  EXPECT_EQ(line["portals"], 12);
  EXPECT_GT(line["triangles"].get<int>(), 10000);
  const auto doc = read_json(scene);
  int window_portals = 0;
  for (const auto& p : doc["portals"])
    window_portals += p["name"].get<std::string>().find("Fenster") != std::string::npos ? 1 : 0;
  EXPECT_EQ(window_portals, 11);
  EXPECT_NEAR(doc["site"]["latitude"].get<double>(), 49.1, 0.01);
  EXPECT_NEAR(doc["site"]["north_deg"].get<double>(), 50, 1e-6);
  EXPECT_EQ(doc["sensors"].size(), 7u);
  // The scene loads: every mesh file, material and portal it names is there.
  const auto info = run_relight("info '" + scene.string() + "'");
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("portals: 12"), std::string::npos) << info.out;
}

TEST(ImportCommand, OneStoreyByNumberOrNameAndAStoreyTheModelLacksIsAnInputError) {
  if (!fs::exists(kFzk) || !ifc_reader_installed()) GTEST_SKIP() << "no model or IFC reader";
  TempDir dir;
  const fs::path scene = dir.path() / "ground.json";
  for (const std::string storey : {"1", "Erdgeschoss"}) {
    const auto r = run_relight("import '" + kFzk.string() + "' -o '" + scene.string() +
                               "' --storey " + storey);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto line = nlohmann::json::parse(r.out);
    EXPECT_EQ(line["storeys"], 1);
    EXPECT_EQ(line["spaces"], 6);  // the gallery is upstairs
    EXPECT_EQ(line["windows"], 9);
  }
  const auto bad =
      run_relight("import '" + kFzk.string() + "' -o '" + scene.string() + "' --storey 3");
  expect_input_error(
      bad, "--storey 3: no such storey; the model's storeys from the lowest: 1 \"Erdgeschoss\"");
}

// A quad wound counter-clockwise seen from its front (`front`), else the other way, over the
// same diagonal.
std::string quad(const std::vector<std::array<double, 3>>& p, bool front, int& vertices) {
  std::string s;
  for (const auto& v : p)
    s += "v " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) +
         "\n";
  const int b = vertices;
  vertices += 4;
  const auto f = [&](int i) { return std::to_string(b + i + 1); };
  return s +
         (front ? "f " + f(0) + " " + f(1) + " " + f(2) + " " + f(3)
                : "f " + f(0) + " " + f(3) + " " + f(2) + " " + f(1)) +
         "\n";
}

// A 4 × 3 × 5 m room with a 1 × 1 m skylight; `inward`: its faces wound to face the room.
std::string skylight_room(bool inward) {
  int n = 0;
  std::string obj = "mtllib room.mtl\nusemtl plaster\n";
  obj += quad({{0, 0, 0}, {0, 0, 5}, {4, 0, 5}, {4, 0, 0}}, inward, n);  // floor
  obj += quad({{0, 0, 0}, {0, 3, 0}, {0, 3, 5}, {0, 0, 5}}, inward, n);  // x = 0
  obj += quad({{4, 0, 0}, {4, 0, 5}, {4, 3, 5}, {4, 3, 0}}, inward, n);  // x = 4
  obj += quad({{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}}, inward, n);  // z = 0
  obj += quad({{0, 0, 5}, {0, 3, 5}, {4, 3, 5}, {4, 0, 5}}, inward, n);  // z = 5
  const auto ceiling = [&](double x0, double z0, double x1, double z1) {
    return quad({{x0, 3, z0}, {x1, 3, z0}, {x1, 3, z1}, {x0, 3, z1}}, inward, n);
  };
  obj += ceiling(0, 0, 4, 2) + ceiling(0, 3, 4, 5) + ceiling(0, 2, 1.5, 3) + ceiling(2.5, 2, 4, 3);
  obj += "usemtl glass\n" + ceiling(1.5, 2, 2.5, 3);
  return obj;
}

struct ImportedRoom {
  nlohmann::json line;
  std::vector<double> lux;
};

ImportedRoom import_and_probe(const TempDir& dir, const std::string& name, bool inward) {
  const fs::path folder = dir.path() / name;
  fs::create_directories(folder);
  std::ofstream(folder / "room.mtl")
      << "newmtl plaster\nKd 0.7 0.7 0.7\nnewmtl glass\nKd 0 0 0\nd 0.2\n";
  std::ofstream(folder / "room.obj") << skylight_room(inward);
  const fs::path scene = folder / "scene.json", rlt = folder / "scene.rlt",
                 csv = folder / "probe.csv";
  auto r = run_relight("import '" + (folder / "room.obj").string() + "' -o '" + scene.string() +
                       "' --max-edge 0.5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  ImportedRoom room{nlohmann::json::parse(r.out), {}};
  auto doc = read_json(scene);
  EXPECT_EQ(doc["precompute"], nlohmann::json({{"max_edge", 0.5}}));  // --max-edge
  doc["precompute"]["gather_rays"] = 64;
  doc["precompute"]["sensor_gather_rays"] = 512;
  std::ofstream(scene) << doc.dump();
  r = run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("turned"), std::string::npos) << "the import turned them already: " << r.err;
  r = run_relight("probe '" + rlt.string() + "' -o '" + csv.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  room.lux = sensor_lux(csv);
  return room;
}

TEST(ImportCommand, AnObjRoomWithItsNormalsOutIsTurnedAndProbesAsTheCorrectOne) {
  TempDir dir;
  const ImportedRoom correct = import_and_probe(dir, "correct", true);
  const ImportedRoom flipped = import_and_probe(dir, "flipped", false);
  EXPECT_EQ(correct.line["warnings"].size(), 0u) << correct.line.dump();
  ASSERT_EQ(flipped.line["warnings"].size(), 1u) << flipped.line.dump();
  EXPECT_EQ(flipped.line["warnings"][0].get<std::string>().rfind("turned 18 of 18 triangles", 0),
            0u)
      << flipped.line.dump();
  for (const auto* room : {&correct, &flipped}) {
    EXPECT_EQ(room->line["portals"], 1);  // the skylight: glass by its dissolve
    EXPECT_EQ(room->line["spaces"], 1);   // sensors on the floor found
  }
  // 4 × 5 m less the 0.5 m border, every 0.25 m: 12 × 16 points.
  ASSERT_EQ(correct.lux.size(), 192u);
  ASSERT_EQ(flipped.lux.size(), correct.lux.size());
  double mean = 0;
  for (std::size_t i = 0; i < correct.lux.size(); ++i) {
    EXPECT_NEAR(flipped.lux[i], correct.lux[i], 2e-3 * correct.lux[i]) << i;
    mean += correct.lux[i] / static_cast<double>(correct.lux.size());
  }
  EXPECT_GT(mean, 10.0);  // daylight through the skylight under 10 klx of overcast sky
}

TEST(ImportCommand, BadModelsAreInputErrorsNamingTheFile) {
  TempDir dir;
  const fs::path out = dir.path() / "scene.json";
  const fs::path text = dir.write("notes.ifc", "not a model\n");
  expect_input_error(run_relight("import '" + text.string() + "' -o '" + out.string() + "'"),
                     text.string() + ": not an IFC file");
  const fs::path cut = dir.write("cut.ifc", "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=IFCWALL(");
  expect_input_error(run_relight("import '" + cut.string() + "' -o '" + out.string() + "'"),
                     cut.string() + ": truncated");
  const fs::path drawing = dir.write("plan.dwg", "AC1032");
  expect_input_error(run_relight("import '" + drawing.string() + "' -o '" + out.string() + "'"),
                     drawing.string() + ": not a model relight imports");
  const fs::path points = dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_input_error(run_relight("import '" + points.string() + "' -o '" + out.string() + "'"),
                     points.string() + ": no faces");
  if (ifc_reader_installed()) {
    const fs::path empty = dir.write("empty.ifc",
                                     "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_"
                                     "NAME('empty.ifc','',(''),(''),'','','');\n"
                                     "FILE_SCHEMA(('IFC4'));\nENDSEC;\nDATA;\n#1=IFCPROJECT('"
                                     "0YvctVUKr0kugbFTf53O9L',$,'empty',$,$,$,$,$,$);\n"
                                     "ENDSEC;\nEND-ISO-10303-21;\n");
    expect_input_error(run_relight("import '" + empty.string() + "' -o '" + out.string() + "'"),
                       empty.string() + ": the model has no geometry");
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace relight
