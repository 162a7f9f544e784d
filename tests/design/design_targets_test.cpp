// TARGETS.json (design/design_targets.h): what it accepts, and bad targets refused with the
// JSON path (exit 2 in `relight optimize`).
#include <gtest/gtest.h>

#include "common/input_error.h"
#include "design/design_targets.h"
#include "scene/scene.h"

namespace relight {
namespace {

Scene two_set_scene() {
  Scene scene;
  scene.sensors.push_back({"desk", {{0, 0.8, 0}, {1, 0.8, 0}}});
  scene.sensors.push_back({"wall", {{0, 1, 0}}});
  Luminaire a, b;
  a.name = "a";
  b.name = "b";
  scene.luminaires = {a, b};
  return scene;
}

DesignTargets parse(const std::string& json) {
  return parse_design_targets(nlohmann::json::parse(json), two_set_scene(), "t.json");
}

std::string error_of(const std::string& json) {
  try {
    parse(json);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DesignTargets, ReadsTargetsInSceneOrderAndLuminaireFreedoms) {
  const DesignTargets t = parse(R"({
    "sensors": { "wall": { "e_max": 800 }, "desk": { "u0_min": 0.6, "em_min": 500 } },
    "luminaires": { "b": { "dimmer": [0.2, 0.9], "aim_cone_deg": 15 }, "a": { "fixed": true } },
    "objective": "uniformity", "power_w": { "a": 36 } })");
  ASSERT_EQ(t.targets.size(), 3U);
  EXPECT_EQ(t.targets[0].set, 0U);
  EXPECT_EQ(t.targets[0].kind, TargetKind::kEmMin);
  EXPECT_EQ(t.targets[0].value, 500);
  EXPECT_EQ(t.targets[1].kind, TargetKind::kU0Min);
  EXPECT_EQ(t.targets[2].set, 1U);
  EXPECT_EQ(t.targets[2].kind, TargetKind::kEMax);
  EXPECT_TRUE(t.luminaires[0].fixed);
  EXPECT_EQ(t.luminaires[0].power_w, 36);
  EXPECT_EQ(t.luminaires[1].dimmer_lo, 0.2);
  EXPECT_EQ(t.luminaires[1].dimmer_hi, 0.9);
  EXPECT_EQ(t.luminaires[1].aim_cone_deg, 15);
  EXPECT_EQ(t.objective, DesignObjective::kUniformity);
}

TEST(DesignTargets, LuminairesNotNamedAreFreeDimmersFromZeroToOne) {
  const DesignTargets t = parse(R"({"sensors": {"desk": {"em_min": 300}}})");
  for (const LuminaireFreedom& l : t.luminaires) {
    EXPECT_FALSE(l.fixed);
    EXPECT_EQ(l.dimmer_lo, 0);
    EXPECT_EQ(l.dimmer_hi, 1);
    EXPECT_EQ(l.aim_cone_deg, 0);
  }
  EXPECT_EQ(t.objective, DesignObjective::kPower);
}

TEST(DesignTargets, BadTargetsNameTheirJsonPath) {
  EXPECT_NE(error_of(R"({"sensors": {"hall": {"em_min": 300}}})")
                .find("t.json:/sensors/hall: no sensor set named \"hall\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_min": 300}}, "luminaires": {"c": {}}})")
                .find("t.json:/luminaires/c: no luminaire named \"c\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_min": 500, "em_max": 300}}})")
                .find("t.json:/sensors/desk/em_min: is above em_max"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"e_min": 500, "e_max": 300}}})")
                .find("/sensors/desk/e_min: is above e_max"),
            std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"sensors": {"desk": {"em_min": 1}}, "luminaires": {"a": {"dimmer": [0.8, 0.2]}}})")
          .find("/luminaires/a/dimmer/0: is above hi"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {}})").find("no target"), std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"u0_min": 1.5}}})").find("/sensors/desk/u0_min"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_min": -1}}})").find("/sensors/desk/em_min"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_mn": 1}}})").find("em_mn"), std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_min": 1}}, "objective": "cost"})")
                .find("/objective: expected \"power\" or \"uniformity\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"u0_min": 0.5}}, "objective": "uniformity"})")
                .find("needs a level"),
            std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"sensors": {"desk": {"em_min": 1}}, "luminaires": {"a": {"fixed": true, "dimmer": [0, 1]}}})")
          .find("/luminaires/a/dimmer: a fixed luminaire"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"sensors": {"desk": {"em_min": 1}}, "luminaires": {"a": {"aim_cone_deg": 120}}})")
          .find("/luminaires/a/aim_cone_deg"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"sensors": {"desk": {"em_min": 1}}, "power_w": {"z": 3}})")
                .find("/power_w/z: no luminaire"),
            std::string::npos);
}

}  // namespace
}  // namespace relight
