// A top-level environment through the visibility cuts (Iwasaki et al., Cyberworlds, §V–VI): a box
// on an open floor under a CIE sky with a sun, `relight precompute` building the self-visibility
// cuts at 8,192 directions. `relight probe` (every bounce) against `relight reference` on sensors
// in the sun, in the box's shadow and beside it; `relight render
// --max-bounces 1` against `relight reference --max-bounces 1` (256 samples a pixel): 8 × 8-
// pixel block means of luminance within 3 % on average for a Lambertian box and for a steel one
// (roughness 0.3) shaded toward the eye through its vertices' cuts, and for a movable crate of
// either on the floor and a paint crate on a steel floor, before and after it moves; a state
// that turns the sun moves the shadow as the reference does.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "agreement.h"
#include "image/image_exr.h"
#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::TempDir;

// A 0.8 × 0.6 × 0.8 m box of `box` (a material) on an 8 × 8 m floor under a clear CIE sky
// whose sun stands 40° high in the south-west; sensors on the floor in the sun, in the box's
// shadow and beside it.
std::string showroom(const std::string& box) {
  std::string text = R"({
    "materials": {
      "floor": {"albedo": [0.5, 0.45, 0.4]},
      "paint": {"albedo": [0.7, 0.7, 0.7]},
      "steel": {"albedo": [0.8, 0.8, 0.82], "metallic": 1, "roughness": 0.3}
    },
    "geometry": [
      {"type": "quad", "corner": [-4, 0, -4], "u": [0, 0, 8], "v": [8, 0, 0], "material": "floor"},
      {"type": "box", "min": [-0.4, 0, -0.4], "max": [0.4, 0.6, 0.4], "material": "BOX"}
    ],
    "environment": {"type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
                    "sun": {"azimuth_deg": 225, "altitude_deg": 40}, "sun_illuminance": 60000},
    "sensors": [
      {"name": "floor", "normal": [0, 1, 0],
       "points": [[-2, 0, 2], [1.5, 0, -1.5], [0.5, 0, -0.5], [0.2, 0, -0.8], [0, 0, 0.7],
                  [-0.7, 0, 0], [0.6, 0, 0.1], [2.5, 0, 1]]}
    ],
    "precompute": {"max_edge": 0.1, "gather_rays": 256, "cuts": {"directions": 8192}},
    "cameras": [{"name": "view", "eye": [2.2, 2.0, -2.2], "target": [0.2, 0.2, 0.1], "fov_deg": 40}]
  })";
  text.replace(text.find("BOX"), 3, box);
  return text;
}

struct Showroom {
  TempDir dir;
  fs::path scene, rlt;
};

void precompute(Showroom& s, const std::string& box) {
  s.scene = s.dir.path() / "showroom.json";
  s.rlt = s.dir.path() / "showroom.rlt";
  std::ofstream(s.scene) << showroom(box);
  const CommandResult r = run_relight("precompute '" + s.scene.string() + "' -o '" +
                                      s.rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// Block agreement of `relight render --max-bounces 1` (per vertex) with the reference's direct
// light, under `state` when not empty.
testing::BlockAgreement direct_image_agreement(const Showroom& s, const std::string& state) {
  const std::string size = " --width 64 --height 48 --max-bounces 1 ";
  const std::string with_state = state.empty() ? "" : " --state '" + state + "'";
  const fs::path fast = s.dir.path() / "fast.exr", truth = s.dir.path() / "reference.exr";
  CommandResult r = run_relight("render '" + s.rlt.string() + "'" + with_state + size + "-o '" +
                                fast.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + s.scene.string() + "'" + with_state + " --spp 256 --seed 3" +
                  size + "-o '" + truth.string() + "' --no-progress");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return testing::compare_blocks(read_exr(fast), read_exr(truth), 8);
}

TEST(EnvironmentCuts, ProbeFollowsTheReferenceInTheSunInTheShadowAndBesideTheBox) {
  Showroom s;
  precompute(s, "paint");
  const fs::path fast = s.dir.path() / "fast.csv", truth = s.dir.path() / "reference.csv";
  CommandResult r = run_relight("probe '" + s.rlt.string() + "' -o '" + fast.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + s.scene.string() + "' --spp 16384 --seed 5 --sensors-out '" +
                  truth.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> e = testing::sensor_lux(fast), ref = testing::sensor_lux(truth);
  ASSERT_EQ(e.size(), 8u);
  double mean = 0, worst = 0, lowest = 1e9, highest = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double d = std::abs(e[i] - ref[i]) / ref[i];
    std::printf("  sensor %zu: %.0f lx, reference %.0f lx (%.2f %%)\n", i, e[i], ref[i], 100 * d);
    mean += d / static_cast<double>(e.size());
    worst = std::max(worst, d);
    lowest = std::min(lowest, ref[i]);
    highest = std::max(highest, ref[i]);
  }
  std::printf("showroom probe: mean %.2f %%, worst %.2f %%\n", 100 * mean, 100 * worst);
  EXPECT_GT(highest, 3 * lowest);  // sensors in the sun and in the shadow
  EXPECT_LT(mean, 0.02);
  EXPECT_LT(worst, 0.05);
}

TEST(EnvironmentCuts, DirectLightImagesMatchTheReferenceForDiffuseAndGlossyBoxes) {
  for (const std::string box : {"paint", "steel"}) {
    Showroom s;
    precompute(s, box);
    const testing::BlockAgreement a = direct_image_agreement(s, "");
    std::printf("%s box, direct light, %d blocks: mean %.2f %%, worst %.2f %%\n", box.c_str(),
                a.blocks, 100 * a.mean, 100 * a.worst);
    EXPECT_TRUE(a.finite) << box;
    EXPECT_EQ(a.blocks, 48) << box;
    EXPECT_LT(a.mean, 0.03) << box;
  }
}

TEST(EnvironmentCuts, ATurnedSunMovesTheShadowAsTheReferenceDoes) {
  Showroom s;
  precompute(s, "paint");
  const fs::path state = s.dir.path() / "state.json";
  std::ofstream(state) << R"({"environment": {"type": "cie_sky", "sky_type": 12,
      "horizontal_illuminance": 15000, "sun": {"azimuth_deg": 120, "altitude_deg": 30},
      "sun_illuminance": 60000}})";
  const testing::BlockAgreement a = direct_image_agreement(s, state.string());
  std::printf("turned sun, direct light, %d blocks: mean %.2f %%, worst %.2f %%\n", a.blocks,
              100 * a.mean, 100 * a.worst);
  EXPECT_TRUE(a.finite);
  EXPECT_LT(a.mean, 0.03);
}

// The box as a movable object ("crate"): its shadow through its visibility cut field (`spheres`
// spheres of 6 · points² points; the default field is 32 × 6 · 32²) and, within the field's
// inner sphere, traced; its own light through its vertices' cuts, the static floor's coarse
// view and the environment turned into its frame.
void precompute_with_crate(Showroom& s, const std::string& material, int spheres = 12,
                           int points = 16, const std::string& floor = "floor") {
  nlohmann::json doc = nlohmann::json::parse(showroom(material));
  doc["geometry"][0]["material"] = floor;
  doc["objects"] = {{{"name", "crate"}, {"geometry", {doc["geometry"][1]}}}};
  doc["geometry"].erase(1);
  doc["precompute"]["cuts"] = {
      {"directions", 8192}, {"sphere_count", spheres}, {"sphere_points", points}};
  s.scene = s.dir.path() / "showroom.json";
  s.rlt = s.dir.path() / "showroom.rlt";
  std::ofstream(s.scene) << doc.dump();
  const CommandResult r = run_relight("precompute '" + s.scene.string() + "' -o '" +
                                      s.rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// A paint and a steel crate on the diffuse floor, and a paint crate on a steel floor (roughness
// 0.3), whose reflection of the sky the crate blocks where it stands in it — between the eye
// and the crate the mirror directions pass through it (without the objects' fields in the
// floor's glossy view: 24.7 % and 18.8 % mean, against 1.1 % and 1.9 %).
TEST(EnvironmentCuts,
     AMovableCratesDirectLightMatchesTheReferenceBeforeAndAfterItMovesOnAGlossyFloorToo) {
  const std::pair<std::string, std::string> cases[] = {
      {"paint", "floor"}, {"steel", "floor"}, {"paint", "steel"}};
  for (const auto& [material, floor] : cases) {
    Showroom s;
    precompute_with_crate(s, material, 12, 16, floor);
    const fs::path state = s.dir.path() / "moved.json";
    std::ofstream(state)
        << R"({"objects": {"crate": {"translate": [0.5, 0, 0.3], "rotate_deg": 25}}})";
    for (const std::string& st : {std::string(), state.string()}) {
      const testing::BlockAgreement a = direct_image_agreement(s, st);
      std::printf("%s crate on %s %s, direct light, %d blocks: mean %.2f %%, worst %.2f %%\n",
                  material.c_str(), floor.c_str(), st.empty() ? "as placed" : "moved and turned",
                  a.blocks, 100 * a.mean, 100 * a.worst);
      EXPECT_TRUE(a.finite) << material << floor << st;
      EXPECT_LT(a.mean, 0.03) << material << floor << st;
    }
  }
}

// Every bounce with the crate in place and moved: the objects' term (sources/objects/
// object_lighting.h) bounces the environment's light on and around them. Sensors on the floor
// and on the crate's sides; the field at 16 × 6 · 32² (at 12 × 6 · 16² the floor 0.9 m from
// the crate's centre and 0.13 m inside its shadow's edge reads 22 % high: the samples 8.6 cm
// apart there straddle the edge).
TEST(EnvironmentCuts, ProbeWithAMovableCrateFollowsTheReferenceWithEveryBounce) {
  Showroom s;
  precompute_with_crate(s, "paint", 16, 32);
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(s.scene));
  doc["sensors"].push_back({{"name", "crate sides"},
                            {"normal", {1, 0, 0}},
                            {"points", {{0.41, 0.3, 0.0}, {0.41, 0.1, -0.2}}}});
  doc["sensors"].push_back(
      {{"name", "crate west"}, {"normal", {-1, 0, 0}}, {"points", {{-0.41, 0.3, 0.0}}}});
  std::ofstream(s.scene) << doc.dump();
  CommandResult r = run_relight("precompute '" + s.scene.string() + "' -o '" + s.rlt.string() +
                                "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path moved = s.dir.path() / "moved.json";
  std::ofstream(moved) << R"({"objects": {"crate": {"translate": [-1.2, 0, 1.4]}}})";
  for (const bool move : {false, true}) {
    const std::string state = move ? " --state '" + moved.string() + "'" : "";
    const fs::path fast = s.dir.path() / "fast.csv", truth = s.dir.path() / "reference.csv";
    r = run_relight("probe '" + s.rlt.string() + "'" + state + " -o '" + fast.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_relight("reference '" + s.scene.string() + "'" + state +
                    " --spp 16384 --seed 9 --sensors-out '" + truth.string() + "' --no-progress");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<double> e = testing::sensor_lux(fast), ref = testing::sensor_lux(truth);
    // Moved away, the crate's sensors hang in the air where it stood: the floor's alone.
    const std::size_t count = move ? 8 : e.size();
    double mean = 0, worst = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const double d = std::abs(e[i] - ref[i]) / ref[i];
      mean += d / static_cast<double>(count);
      worst = std::max(worst, d);
    }
    std::printf("crate %s, every bounce, %zu sensors: mean %.2f %%, worst %.2f %%\n",
                move ? "moved" : "as placed", count, 100 * mean, 100 * worst);
    EXPECT_LT(mean, 0.02) << move;
    EXPECT_LT(worst, 0.05) << move;
  }
}

TEST(EnvironmentCuts, WhatTheTransferCannotLightIsRefused) {
  const TempDir dir;
  const fs::path scene = dir.path() / "lit.json", rlt = dir.path() / "lit.rlt";
  nlohmann::json doc = nlohmann::json::parse(showroom("paint"));
  doc["luminaires"] = {
      {{"name", "lamp"},
       {"position", {0, 3, 0}},
       {"aim", {0, -1, 0}},
       {"distribution", {{"type", "cosine_power"}, {"candela", 500}, {"exponent", 1}}}}};
  doc["precompute"]["max_edge"] = 0.5;
  std::ofstream(scene) << doc.dump();
  CommandResult r =
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("probe '" + rlt.string() + "' --max-bounces 1");
  testing::expect_input_error(r, rlt.string());
  EXPECT_NE(r.err.find("--max-bounces 1"), std::string::npos) << r.err;

  // A state's environment for a scene precomputed without one: no cuts to light it.
  doc.erase("environment");
  const fs::path plain = dir.path() / "plain.json", plain_rlt = dir.path() / "plain.rlt",
                 state = dir.path() / "state.json";
  std::ofstream(plain) << doc.dump();
  std::ofstream(state) << R"({"environment": {"type": "uniform", "luminance": 100}})";
  r = run_relight("precompute '" + plain.string() + "' -o '" + plain_rlt.string() +
                  "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("probe '" + plain_rlt.string() + "' --state '" + state.string() + "'");
  testing::expect_input_error(r, state.string() + ":/environment: the scene has no top-level");
}

}  // namespace
}  // namespace relight
