// OBJ import (scene/obj_import.h): geometry, materials and "FILE:LINE: reason" for broken files.
#include "scene/obj_import.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/input_error.h"
#include "scene/mesh_import.h"
#include "support/mesh_import_error.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(RELIGHT_TEST_DATA) / "meshes";

class ObjImport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("relight_obj_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // The InputError message of importing `text` as an OBJ file.
  std::string error_of(const std::string& text) const {
    SCOPED_TRACE(text);
    return testing::mesh_import_error(write("broken.obj", text));
  }

  std::string at(int line) const {
    return (dir_ / "broken.obj").string() + ":" + std::to_string(line) + ": ";
  }

  fs::path dir_;
};

double area(const ImportedMesh& m, const Triangle& t) {
  return 0.5 * length(cross(m.positions[t[1]] - m.positions[t[0]],
                            m.positions[t[2]] - m.positions[t[0]]));
}

TEST_F(ObjImport, CubeQuadsBecomeOutwardTrianglesWithMtlAlbedo) {
  const ImportedMesh mesh = import_mesh(kMeshes / "two_material_cube.obj");
  ASSERT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.positions[7], (Vec3{1, 1, 1}));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  ASSERT_EQ(mesh.triangle_material.size(), 12u);
  ASSERT_EQ(mesh.materials.size(), 2u);
  EXPECT_EQ(mesh.materials[0].name, "white");
  EXPECT_NEAR(mesh.materials[0].albedo.g, 0.7, 1e-6);
  EXPECT_EQ(mesh.materials[1].name, "red");
  EXPECT_NEAR(mesh.materials[1].albedo.r, 0.9, 1e-6);
  EXPECT_NEAR(mesh.materials[1].albedo.g, 0.1, 1e-6);
  EXPECT_NEAR(mesh.materials[1].albedo.b, 0.05, 1e-6);
  double total = 0;
  for (std::size_t t = 0; t < 12; ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    const Vec3 n = normalize(cross(b - a, c - a));
    const Vec3 centre = (a + b + c) / 3.0;
    EXPECT_GT(dot(n, centre - Vec3{0.5, 0.5, 0.5}), 0.49) << "triangle " << t << " faces inward";
    EXPECT_EQ(mesh.triangle_material[t], n.z > 0.5 ? 1u : 0u);
    total += area(mesh, tri);
  }
  EXPECT_NEAR(total, 6.0, 1e-12);
}

TEST_F(ObjImport, ExtensionIsCaseInsensitive) {
  const fs::path path = write("quad.OBJ", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const ImportedMesh mesh = import_mesh(path);
  EXPECT_EQ(mesh.triangles.size(), 2u);
}

TEST_F(ObjImport, MissingMtlGivesDefaultGreyMaterial) {
  const fs::path path =
      write("tri.obj", "mtllib nowhere.mtl\nusemtl paint\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const ImportedMesh mesh = import_mesh(path);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].name, "default");
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.r, 0.8);
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.g, 0.8);
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.b, 0.8);
  EXPECT_EQ(mesh.triangle_material, (std::vector<std::uint32_t>{0}));
}

TEST_F(ObjImport, CoordinatesKeepDoublePrecisionAndForwardIndicesWork) {
  // Faces may name vertices defined further down; CRLF line ends are fine.
  const fs::path path = write(
      "far.obj", "f 1 2 3\r\nv 1000000.123456 0 0\r\nv 1000001 0 0\r\nv 1000000 1 0.000001\r\n");
  const ImportedMesh mesh = import_mesh(path);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_DOUBLE_EQ(mesh.positions[0].x, 1000000.123456);
  EXPECT_DOUBLE_EQ(mesh.positions[2].z, 0.000001);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
}

TEST_F(ObjImport, ConcavePolygonIsEarClippedKeepingWinding) {
  // An L-shaped hexagon (area 3), counter-clockwise about +z; a fan from corner 0 would
  // cover area outside it.
  const fs::path path = write("l.obj",
                              "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
                              "f 4 5 6 1 2 3\n");
  const ImportedMesh mesh = import_mesh(path);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  double total = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                         mesh.positions[t[2]] - mesh.positions[t[0]]);
    EXPECT_GT(n.z, 0.0);
    total += area(mesh, t);
  }
  EXPECT_NEAR(total, 3.0, 1e-12);
}

TEST_F(ObjImport, FaceIndexOutOfRangeNamesItsLine) {
  const std::string message = error_of("v 0 0 0\nv 1 0 0\n# comment\nv 0 1 0\nf 1 2 4\n");
  EXPECT_EQ(message.rfind(at(5), 0), 0u) << message;
}

TEST_F(ObjImport, ForwardIndexPastTheLastVertexNamesItsLine) {
  const std::string message = error_of("v 0 0 0\nf 1 2 9\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(message.rfind(at(2), 0), 0u) << message;
}

TEST_F(ObjImport, NegativeIndexBeforeFirstVertexNamesItsLine) {
  const std::string message = error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
  EXPECT_EQ(message.rfind(at(4), 0), 0u) << message;
}

TEST_F(ObjImport, ZeroOrNonNumericFaceIndexNamesItsLine) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n").rfind(at(4), 0), 0u);
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n").rfind(at(4), 0), 0u);
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n").rfind(at(4), 0), 0u);
}

TEST_F(ObjImport, NonNumericCoordinateNamesItsLine) {
  const std::string message = error_of("v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(message.rfind(at(2), 0), 0u) << message;
  EXPECT_NE(message.find("'zero'"), std::string::npos) << message;
}

TEST_F(ObjImport, MissingCoordinateNamesItsLine) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n").rfind(at(3), 0), 0u);
}

TEST_F(ObjImport, FaceWithTwoVerticesNamesItsLine) {
  const std::string message = error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n");
  EXPECT_EQ(message.rfind(at(5), 0), 0u) << message;
}

TEST_F(ObjImport, NanOrInfiniteCoordinateNamesItsLine) {
  EXPECT_EQ(error_of("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n").rfind(at(2), 0), 0u);
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n").rfind(at(3), 0), 0u);
  EXPECT_EQ(error_of("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n").rfind(at(2), 0), 0u);
}

TEST_F(ObjImport, FileWithoutFacesIsAnError) {
  const std::string message = error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
  EXPECT_EQ(message.rfind((dir_ / "broken.obj").string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("no faces"), std::string::npos) << message;
}

TEST_F(ObjImport, MissingFileAndUnknownExtensionAreInputErrors) {
  EXPECT_THROW(import_mesh(dir_ / "absent.obj"), InputError);
  EXPECT_THROW(import_mesh(write("mesh.stl", "solid x\n")), InputError);
}

}  // namespace
}  // namespace relight
