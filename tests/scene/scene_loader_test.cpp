// Scene JSON loading: primitives, orientation, sensors, defaults, and errors that name
// the JSON path.
#include <gtest/gtest.h>

#include "common/input_error.h"
#include "scene/scene_loader.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

using nlohmann::json;

json minimal_scene() {
  return json::parse(R"({
    "materials": { "white": { "albedo": [0.8, 0.8, 0.8] },
                   "glass": { "albedo": [0, 0, 0], "portal": true } },
    "geometry": [
      { "type": "quad", "corner": [0,0,0], "u": [0,0,2], "v": [3,0,0], "material": "white" },
      { "type": "box", "min": [0,0,0], "max": [1,2,3], "normals": "inward", "material": "white" },
      { "type": "sphere", "center": [0,1,0], "radius": 0.5, "subdivisions": 2, "material": "glass" }
    ],
    "luminaires": [ { "name": "a", "position": [0,2,0],
                      "distribution": { "type": "isotropic", "candela": 100 } } ],
    "sensors": [ { "name": "grid", "grid": { "corner": [0,0,0], "u": [2,0,0], "v": [0,0,1],
                                            "nu": 4, "nv": 2 } } ],
    "cameras": [ { "name": "c", "eye": [0,1,5], "target": [0,1,0] } ]
  })");
}

std::string load_error(const json& scene) {
  try {
    scene_from_json(scene, "scene.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Vec3 triangle_normal(const TriangleSoup& s, std::size_t t) {
  const Triangle& tri = s.triangles[t];
  return normalize(
      cross(s.positions[tri[1]] - s.positions[tri[0]], s.positions[tri[2]] - s.positions[tri[0]]));
}

TEST(SceneLoader, QuadNormalIsUCrossV) {
  const Scene scene = scene_from_json(minimal_scene(), "scene.json");
  // u = +z, v = +x: u × v = +y.
  EXPECT_NEAR(triangle_normal(scene.geometry, 0).y, 1.0, 1e-12);
  EXPECT_NEAR(triangle_normal(scene.geometry, 1).y, 1.0, 1e-12);
}

TEST(SceneLoader, InwardBoxNormalsPointToTheCentre) {
  const Scene scene = scene_from_json(minimal_scene(), "scene.json");
  const Vec3 centre{0.5, 1, 1.5};
  for (std::size_t t = 2; t < 14; ++t) {
    const Triangle& tri = scene.geometry.triangles[t];
    const Vec3 c = (scene.geometry.positions[tri[0]] + scene.geometry.positions[tri[1]] +
                    scene.geometry.positions[tri[2]]) /
                   3.0;
    EXPECT_GT(dot(triangle_normal(scene.geometry, t), centre - c), 0) << "triangle " << t;
  }
}

TEST(SceneLoader, OutwardSphereHasOutwardNormalsAndVerticesOnTheSphere) {
  const Scene scene = scene_from_json(minimal_scene(), "scene.json");
  ASSERT_EQ(scene.geometry.triangles.size(), 2u + 12u + 20u * 16u);
  const Vec3 centre{0, 1, 0};
  for (std::size_t t = 14; t < scene.geometry.triangles.size(); ++t) {
    const Triangle& tri = scene.geometry.triangles[t];
    const Vec3 c = (scene.geometry.positions[tri[0]] + scene.geometry.positions[tri[1]] +
                    scene.geometry.positions[tri[2]]) /
                   3.0;
    EXPECT_GT(dot(triangle_normal(scene.geometry, t), c - centre), 0);
    EXPECT_NEAR(length(scene.geometry.positions[tri[0]] - centre), 0.5, 1e-12);
  }
  EXPECT_TRUE(scene.materials[scene.geometry.triangle_material.back()].portal);
}

TEST(SceneLoader, GridSensorsSitAtCellCentresInRowMajorOrder) {
  const Scene scene = scene_from_json(minimal_scene(), "scene.json");
  ASSERT_EQ(scene.sensors.size(), 1u);
  const SensorSet& s = scene.sensors[0];
  ASSERT_EQ(s.points.size(), 8u);
  // index j*nu + i -> corner + (i+½)/nu·u + (j+½)/nv·v
  EXPECT_NEAR(s.points[0].x, 0.25, 1e-12);
  EXPECT_NEAR(s.points[0].z, 0.25, 1e-12);
  EXPECT_NEAR(s.points[5].x, 0.75, 1e-12);
  EXPECT_NEAR(s.points[5].z, 0.75, 1e-12);
  EXPECT_NEAR(s.normal.y, 1.0, 1e-12);  // default: horizontal work plane
}

TEST(SceneLoader, LuminaireDefaultsAimDownWithC0AlongX) {
  const Scene scene = scene_from_json(minimal_scene(), "scene.json");
  const Luminaire& l = scene.luminaires[0];
  EXPECT_EQ(l.aim, (Vec3{0, -1, 0}));
  EXPECT_EQ(l.c0, (Vec3{1, 0, 0}));
  EXPECT_DOUBLE_EQ(luminance(l.color), 1.0);
  EXPECT_DOUBLE_EQ(l.dimmer, 1.0);
}

TEST(SceneLoader, ColourIsNormalisedToUnitLuminance) {
  json scene = minimal_scene();
  scene["luminaires"][0]["color"] = {1.0, 0.5, 0.25};
  const Luminaire l = scene_from_json(scene, "scene.json").luminaires[0];
  EXPECT_NEAR(luminance(l.color), 1.0, 1e-12);
  EXPECT_NEAR(l.color.g / l.color.r, 0.5, 1e-12);
}

TEST(SceneLoader, UnknownKeyNamesItsJsonPath) {
  json scene = minimal_scene();
  scene["geometry"][1]["colour"] = "red";
  EXPECT_EQ(load_error(scene).rfind("scene.json:/geometry/1/colour: unknown key", 0), 0u)
      << load_error(scene);
}

TEST(SceneLoader, NegativeRadiusIsRejected) {
  json scene = minimal_scene();
  scene["geometry"][2]["radius"] = -0.5;
  EXPECT_EQ(load_error(scene), "scene.json:/geometry/2/radius: must be positive, got -0.5");
}

TEST(SceneLoader, InfiniteNumberIsRejected) {
  json scene = minimal_scene();
  scene["precompute"] = {{"max_edge", std::numeric_limits<double>::infinity()}};
  EXPECT_NE(load_error(scene).find("/precompute/max_edge"), std::string::npos);
}

TEST(SceneLoader, UnknownMaterialAndPrecomputeKeyAreErrors) {
  json scene = minimal_scene();
  scene["geometry"][0]["material"] = "nope";
  EXPECT_NE(load_error(scene).find("/geometry/0/material: unknown material"), std::string::npos);
  scene = minimal_scene();
  scene["precompute"] = {{"max_edges", 0.1}};
  EXPECT_NE(load_error(scene).find("/precompute/max_edges: unknown key"), std::string::npos);
}

// Metallic and roughness (either makes a material glossy, the other at the glTF default), 0..1 with
// the JSON path; glass needs no albedo and takes neither key.
TEST(SceneLoader, MetallicRoughnessKeysMakeAMaterialGlossy) {
  json scene = minimal_scene();
  scene["materials"]["steel"] = {{"albedo", {0.5, 0.5, 0.5}}, {"metallic", 1}, {"roughness", 0.3}};
  scene["materials"]["satin"] = {{"albedo", {0.5, 0.5, 0.5}}, {"roughness", 0.2}};
  scene["materials"]["clear"] = {{"portal", true}};
  const Scene s = scene_from_json(scene, "scene.json");
  const auto named = [&](const std::string& name) {
    for (const Material& m : s.materials) {
      if (m.name == name) return m;
    }
    throw std::runtime_error("no material " + name);
  };
  EXPECT_FALSE(named("white").glossy);
  EXPECT_TRUE(named("steel").glossy);
  EXPECT_EQ(named("steel").metallic, 1.0);
  EXPECT_EQ(named("steel").roughness, 0.3);
  EXPECT_TRUE(named("satin").glossy);
  EXPECT_EQ(named("satin").metallic, 0.0);
  EXPECT_TRUE(named("clear").portal);

  scene["materials"]["steel"]["roughness"] = 1.2;
  EXPECT_EQ(load_error(scene), "scene.json:/materials/steel/roughness: must be between 0 and 1, got 1.2");
  scene = minimal_scene();
  scene["materials"]["steel"] = {{"albedo", {0.5, 0.5, 0.5}}, {"metallic", -0.5}};
  EXPECT_EQ(load_error(scene), "scene.json:/materials/steel/metallic: must be between 0 and 1, got -0.5");
  scene = minimal_scene();
  scene["materials"]["glass"]["roughness"] = 0.1;
  EXPECT_EQ(load_error(scene).rfind("scene.json:/materials/glass/roughness: window glass", 0), 0u)
      << load_error(scene);
  scene = minimal_scene();
  scene["materials"]["white"].erase("albedo");
  EXPECT_EQ(load_error(scene).rfind("scene.json:/materials/white: missing required key \"albedo\"", 0),
            0u)
      << load_error(scene);
}

TEST(SceneLoader, MalformedJsonReportsTheLine) {
  testing::TempDir dir;
  const auto file = dir.write("bad.json", "{\n  \"materials\": {},\n  \"geometry\": [,]\n}\n");
  try {
    load_scene(file);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ":3: malformed JSON", 0), 0u) << e.what();
  }
}

TEST(SceneLoader, MissingDistributionFileIsReportedAtItsPath) {
  json scene = minimal_scene();
  scene["luminaires"][0]["distribution"] = {{"type", "ies"}, {"file", "missing.ies"}};
  EXPECT_NE(load_error(scene).find("/luminaires/0/distribution/file: file not found"),
            std::string::npos);
}

TEST(SceneLoader, CurveNeedsMatchingAscendingControlPoints) {
  json scene = minimal_scene();
  scene["luminaires"][0]["distribution"] = {
      {"type", "curve"}, {"gamma_deg", {0, 30, 20}}, {"candela", {1, 2, 3}}};
  EXPECT_NE(load_error(scene).find("angles must ascend"), std::string::npos);
  scene["luminaires"][0]["distribution"] = {
      {"type", "curve"}, {"gamma_deg", {0, 30}}, {"candela", {1, 2, 3}}};
  EXPECT_NE(load_error(scene).find("/distribution/candela"), std::string::npos);
}

}  // namespace
}  // namespace relight

namespace relight {
namespace {

nlohmann::json scene_with_portals(const nlohmann::json& portals) {
  nlohmann::json scene = nlohmann::json::parse(R"({
    "materials": { "wall": { "albedo": [0.5, 0.5, 0.5] },
                   "glass": { "albedo": [0, 0, 0], "portal": true },
                   "skylight": { "albedo": [0, 0, 0], "portal": true } },
    "geometry": [ { "type": "quad", "corner": [0,0,0], "u": [0,0,1], "v": [1,0,0], "material": "glass" } ]
  })");
  scene["portals"] = portals;
  return scene;
}

const char* kSky = R"({ "type": "uniform", "luminance": 5000 })";

TEST(SceneLoaderPortals, PortalsKeepTheirMaterialsAndEnvironment) {
  const nlohmann::json portals = {
      {{"name", "window"}, {"material", "glass"}, {"environment", nlohmann::json::parse(kSky)}},
      {{"name", "roof"},
       {"materials", {"skylight"}},
       {"environment", nlohmann::json::parse(kSky)}}};
  const Scene scene = scene_from_json(scene_with_portals(portals), "p.json");
  ASSERT_EQ(scene.portals.size(), 2u);
  EXPECT_EQ(scene.materials[scene.portals[0].materials.at(0)].name, "glass");
  EXPECT_EQ(scene.materials[scene.portals[1].materials.at(0)].name, "skylight");
  EXPECT_DOUBLE_EQ(scene.portals[0].environment.luminance, 5000);
}

std::string portal_error(const nlohmann::json& portals) {
  try {
    scene_from_json(scene_with_portals(portals), "p.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneLoaderPortals, RulesAreEnforcedWithJsonPaths) {
  const nlohmann::json sky = nlohmann::json::parse(kSky);
  EXPECT_NE(portal_error({{{"name", "w"}, {"material", "wall"}, {"environment", sky}}})
                .find("p.json:/portals/0/material: material \"wall\" is not window glass"),
            std::string::npos);
  EXPECT_NE(portal_error({{{"name", "a"}, {"material", "glass"}, {"environment", sky}},
                          {{"name", "b"}, {"materials", {"glass"}}, {"environment", sky}}})
                .find("/portals/1/materials/0: material \"glass\" already belongs to portal \"a\""),
            std::string::npos);
  EXPECT_NE(
      portal_error(
          {{{"name", "w"}, {"material", "glass"}, {"materials", {"glass"}}, {"environment", sky}}})
          .find("exactly one of"),
      std::string::npos);
  EXPECT_NE(
      portal_error({{{"name", "w"}, {"material", "glass"}, {"environment", {{"type", "starry"}}}}})
          .find("/portals/0/environment/type"),
      std::string::npos);
}

}  // namespace
}  // namespace relight

namespace relight {
namespace {

TEST(SceneLoaderPortals, GlassDefaultsAndShellCheckSettingsAreRead) {
  const nlohmann::json portals = {{{"name", "window"},
                                   {"material", "glass"},
                                   {"environment", nlohmann::json::parse(kSky)},
                                   {"tint", {0.5, 0.6, 0.7}},
                                   {"frost_deg", 12},
                                   {"exterior_distance", 3},
                                   {"shell_tolerance_deg", 2}}};
  const Scene scene = scene_from_json(scene_with_portals(portals), "p.json");
  const Portal& p = scene.portals.at(0);
  EXPECT_EQ(p.tint, (Rgb{0.5, 0.6, 0.7}));
  EXPECT_DOUBLE_EQ(p.frost_deg, 12);
  EXPECT_DOUBLE_EQ(p.exterior_distance, 3);
  EXPECT_DOUBLE_EQ(p.shell_tolerance_deg, 2);
  nlohmann::json bad = portals;
  bad[0]["tint"] = {1.5, 1, 1};
  EXPECT_NE(portal_error(bad).find("/portals/0/tint: a window's tint is a transmittance"),
            std::string::npos);
  bad = portals;
  bad[0]["frost_deg"] = 95;
  EXPECT_NE(portal_error(bad).find("/portals/0/frost_deg: frost_deg must lie in 0..90"),
            std::string::npos);
}

TEST(SceneLoaderExterior, NamedEntriesAreGeometryWithAPivot) {
  nlohmann::json scene = scene_with_portals(nlohmann::json::array());
  scene["exterior"] = {{{"name", "tower"},
                        {"type", "box"},
                        {"min", {4, 0, 10}},
                        {"max", {6, 20, 12}},
                        {"material", "wall"}},
                       {{"type", "quad"},
                        {"corner", {0, 0, 20}},
                        {"u", {1, 0, 0}},
                        {"v", {0, 1, 0}},
                        {"material", "wall"}}};
  const Scene s = scene_from_json(scene, "p.json");
  ASSERT_EQ(s.exterior.size(), 2u);
  EXPECT_EQ(s.exterior[0].name, "tower");
  EXPECT_EQ(s.exterior[0].geometry.triangles.size(), 12u);
  EXPECT_EQ(s.exterior[0].pivot, (Vec3{5, 10, 11}));
  EXPECT_EQ(s.exterior[1].name, "");
  EXPECT_EQ(s.geometry.triangles.size(), 2u);  // the exterior is not interior geometry

  scene["exterior"][1]["name"] = "tower";
  EXPECT_NE(load_error(scene).find("/exterior/1/name: duplicate exterior object \"tower\""),
            std::string::npos);
  scene["exterior"][1]["name"] = "sign";
  scene["exterior"][1]["material"] = "glass";
  EXPECT_NE(load_error(scene).find("/exterior/1: exterior geometry cannot be window glass"),
            std::string::npos);
  scene["exterior"][1]["material"] = "wall";
  scene["exterior"][1]["colour"] = "red";
  EXPECT_NE(load_error(scene).find("/exterior/1/colour: unknown key"), std::string::npos);
}

TEST(SceneLoaderPortals, PortalPrecomputeSettingsAreChecked) {
  nlohmann::json scene = scene_with_portals(nlohmann::json::array());
  scene["precompute"] = {
      {"portal_face_size", 16}, {"portal_sh_order", 4}, {"portal_samples_per_cell", 8}};
  const Scene s = scene_from_json(scene, "p.json");
  EXPECT_EQ(s.precompute.portal_face_size, 16);
  EXPECT_EQ(s.precompute.portal_sh_order, 4);
  EXPECT_EQ(s.precompute.portal_samples_per_cell, 8);
  scene["precompute"]["portal_face_size"] = 24;
  EXPECT_NE(load_error(scene).find("/precompute/portal_face_size: portal_face_size must be a "
                                   "power of two"),
            std::string::npos);
}

}  // namespace
}  // namespace relight
