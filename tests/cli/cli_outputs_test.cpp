// What the commands write: the sensor CSV of the contract, info's counts, image files,
// and the demo's files.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "run_command.h"

namespace relight {
namespace {

using testing::parse_csv;
using testing::read_text;
using testing::run_relight;
using testing::TempDir;

const char* kRoom = R"({
  "materials": { "white": { "albedo": [0.7, 0.6, 0.5] } },
  "geometry": [ { "type": "box", "min": [0,0,0], "max": [3,2.5,3], "normals": "inward",
                  "material": "white" } ],
  "luminaires": [ { "name": "down", "position": [1.5, 2.4, 1.5], "color": [1, 0.8, 0.6],
                    "distribution": { "type": "cosine_power", "candela": 300, "exponent": 2 } } ],
  "sensors": [ { "name": "floor", "grid": { "corner": [0.5, 0, 0.5], "u": [2, 0, 0],
                 "v": [0, 0, 2], "nu": 2, "nv": 3 } } ],
  "cameras": [ { "name": "inside", "eye": [1.5, 1.2, 2.9], "target": [1.5, 1, 0] } ],
  "precompute": { "max_edge": 0.5 }
})";

TEST(CliOutputs, ReferenceSensorCsvHasContractColumnsAndLuxIsY) {
  TempDir dir;
  const auto scene = dir.write("room.json", kRoom);
  const auto csv = dir.path() / "e.csv";
  const auto r = run_relight("reference '" + scene.string() +
                             "' --spp 16 --no-progress --sensors-out '" + csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = parse_csv(read_text(csv));
  ASSERT_EQ(rows.size(), 7u);
  EXPECT_EQ(read_text(csv).substr(0, read_text(csv).find('\n')),
            "sensor,index,x,y,z,nx,ny,nz,lux,r,g,b");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 12u);
    EXPECT_EQ(rows[i][0], "floor");
    EXPECT_EQ(std::stoi(rows[i][1]), static_cast<int>(i - 1));
    const double lux = std::stod(rows[i][8]);
    const double y = 0.2126 * std::stod(rows[i][9]) + 0.7152 * std::stod(rows[i][10]) +
                     0.0722 * std::stod(rows[i][11]);
    EXPECT_NEAR(lux, y, 1e-6 * lux);
    EXPECT_GT(lux, 10.0);
  }
  // Row 4 is (i=1, j=1): corner + 1.5/2·u + 1.5/3·v.
  EXPECT_NEAR(std::stod(rows[4][2]), 2.0, 1e-9);
  EXPECT_NEAR(std::stod(rows[4][4]), 1.5, 1e-9);
  EXPECT_NE(r.out.find("floor: 6 points  Eavg"), std::string::npos) << r.out;
}

TEST(CliOutputs, InfoPrintsCounts) {
  TempDir dir;
  const auto scene = dir.write("room.json", kRoom);
  const auto r = run_relight("info '" + scene.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("triangles: 12\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("luminaires: 1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sensors: 6 in 1 sets\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bounds: [0, 0, 0] .. [3, 2.5, 3] m"), std::string::npos) << r.out;
  // Each 3 m face subdivided to edges <= 0.5 m has many more vertices than the 24 corners.
  const auto at = r.out.find("vertices after preparation: ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stoi(r.out.substr(at + 28)), 200);
}

TEST(CliOutputs, ReferenceWritesPngAndExr) {
  TempDir dir;
  const auto scene = dir.write("room.json", kRoom);
  for (const char* name : {"a.png", "a.exr"}) {
    const auto image = dir.path() / name;
    const auto r =
        run_relight("reference '" + scene.string() +
                    "' --spp 2 --width 40 --height 30 --no-progress -o '" + image.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_GT(std::filesystem::file_size(image), 100u) << name;
  }
}

TEST(CliOutputs, DemoWritesItsFilesAndSaysWhere) {
  TempDir dir;
  const auto out = dir.path() / "demo";
  const auto r =
      run_relight("demo -o '" + out.string() +
                  "' --reference --spp 1 --width 48 --height 32 --no-progress --no-serve");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f :
       {"demo-room.json", "demo-room.rlt", "evening.json", "work.json", "room-evening.png",
        "room-work.png", "room-evening-lux.png", "room-work-lux.png", "work-plane-evening.csv",
        "work-plane-work.csv", "reference.png", "reference.exr", "work-plane-reference.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  EXPECT_NE(r.out.find("demo files in"), std::string::npos);
  EXPECT_NE(r.out.find("bounces"), std::string::npos);
  // A second run reuses the precompute while the scene is unchanged.
  const auto again =
      run_relight("demo -o '" + out.string() + "' --width 48 --height 32 --no-progress --no-serve");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("using the cached precompute"), std::string::npos) << again.out;
  // The scene the demo wrote is a valid scene file.
  EXPECT_EQ(run_relight("info '" + (out / "demo-room.json").string() + "'").exit_code, 0);
}

}  // namespace
}  // namespace relight
