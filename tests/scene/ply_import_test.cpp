// PLY import (scene/ply_import.h): ascii and both binary encodings, mixed scalar types,
// skipped elements and properties, face colours as materials, and InputError for broken files.
#include "scene/ply_import.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "scene/mesh_import.h"
#include "support/mesh_import_error.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(RELIGHT_TEST_DATA) / "meshes";

// Appends scalars in a chosen byte order.
class Bytes {
 public:
  explicit Bytes(bool little_endian) : little_(little_endian) {}
  template <typename T>
  Bytes& put(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      data_ += static_cast<char>(raw[little_ ? i : sizeof(T) - 1 - i]);  // host is little-endian
    }
    return *this;
  }
  const std::string& str() const { return data_; }

 private:
  bool little_;
  std::string data_;
};

class PlyImport : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& bytes) const {
    return dir_.write(name, bytes);
  }

  std::string error_of(const fs::path& path) const { return testing::mesh_import_error(path); }

  testing::TempDir dir_;
};

// Header of a unit square (two faces: a triangle and a quad over 5 vertices), with an extra
// "edge" element with a list between vertices and faces, to be skipped.
std::string square_header(const std::string& format) {
  return "ply\nformat " + format +
         " 1.0\n"
         "comment written by the test\n"
         "element vertex 5\n"
         "property double x\n"
         "property float quality\n"
         "property double y\n"
         "property double z\n"
         "element edge 1\n"
         "property list uchar int vertex_pair\n"
         "element face 2\n"
         "property uchar flags\n"
         "property list uchar int vertex_indices\n"
         "property uchar red\n"
         "property uchar green\n"
         "property uchar blue\n"
         "end_header\n";
}

// Vertices (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0.5,-1,0); faces [0 4 1] grey 128 and
// [0 1 2 3] red (255, 0, 0).
std::string square_body(bool little_endian) {
  Bytes b(little_endian);
  const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, -1, 0}};
  for (const auto& p : xyz) b.put(p[0]).put(0.25f).put(p[1]).put(p[2]);
  b.put(std::uint8_t{2}).put(std::int32_t{0}).put(std::int32_t{1});
  b.put(std::uint8_t{7}).put(std::uint8_t{3});
  b.put(std::int32_t{0}).put(std::int32_t{4}).put(std::int32_t{1});
  b.put(std::uint8_t{128}).put(std::uint8_t{128}).put(std::uint8_t{128});
  b.put(std::uint8_t{0}).put(std::uint8_t{4});
  for (std::int32_t i : {0, 1, 2, 3}) b.put(i);
  b.put(std::uint8_t{255}).put(std::uint8_t{0}).put(std::uint8_t{0});
  return b.str();
}

void expect_square(const ImportedMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.positions[4], (Vec3{0.5, -1, 0}));
  EXPECT_EQ(mesh.positions[2], (Vec3{1, 1, 0}));
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 4, 1}));
  EXPECT_EQ(mesh.triangles[1], (Triangle{0, 1, 2}));  // fan around corner 0
  EXPECT_EQ(mesh.triangles[2], (Triangle{0, 2, 3}));
  ASSERT_EQ(mesh.materials.size(), 2u);
  EXPECT_EQ(mesh.materials[0].name, "rgb(128,128,128)");
  EXPECT_NEAR(mesh.materials[0].albedo.g, 0.2158605, 1e-6);  // sRGB 128 decoded
  EXPECT_EQ(mesh.materials[1].name, "rgb(255,0,0)");
  EXPECT_DOUBLE_EQ(mesh.materials[1].albedo.r, 1.0);
  EXPECT_DOUBLE_EQ(mesh.materials[1].albedo.g, 0.0);
  EXPECT_EQ(mesh.triangle_material, (std::vector<std::uint32_t>{0, 1, 1}));
}

TEST_F(PlyImport, AsciiTetrahedronSkipsExtraPropertiesAndElements) {
  const ImportedMesh mesh = import_mesh(kMeshes / "tetrahedron_ascii.ply");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[3], (Vec3{0, 0, 1}));
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.triangles[3], (Triangle{1, 2, 3}));
  // No face colours: one default material (vertex colours are ignored).
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].name, "default");
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.r, 0.8);
  const Vec3 centre{0.25, 0.25, 0.25};
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    EXPECT_GT(dot(cross(b - a, c - a), (a + b + c) / 3.0 - centre), 0.0);  // outward
  }
}

// An element with no properties holds no data whatever count it declares: 2·10¹⁸ instances of
// one (what make fuzz found spinning the reader) are skipped at once, in ascii and binary.
TEST_F(PlyImport, AnElementWithoutPropertiesIsSkippedWhateverItsCount) {
  for (const std::string format : {"ascii", "binary_little_endian"}) {
    const std::string header = "ply\nformat " + format +
                               " 1.0\nelement camera 2000000000000000000\n"
                               "element vertex 3\nproperty uchar x\nproperty uchar y\n"
                               "property uchar z\nelement face 1\n"
                               "property list uchar uchar vertex_indices\nend_header\n";
    const std::string body = format == "ascii" ? "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
                                               : std::string("\0\0\0\1\0\0\0\1\0\3\0\1\2", 13);
    const ImportedMesh mesh = import_mesh(write("camera.ply", header + body));
    ASSERT_EQ(mesh.positions.size(), 3u) << format;
    EXPECT_EQ(mesh.positions[2], (Vec3{0, 1, 0}));
    EXPECT_EQ(mesh.triangles.size(), 1u);
  }
}

TEST_F(PlyImport, OnlyTheFirstVertexAndFaceElementsAreRead) {
  // A second face element (without colours) and a second vertex element are read past: the
  // mesh is the first vertex element's three points and the first face element's triangle.
  const std::string header =
      "ply\nformat ascii 1.0\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 2\nproperty list uchar int vertex_indices\n"
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n3 2 1 0\n3 0 2 1\n9 9 9\n";
  const ImportedMesh mesh = import_mesh(write("two_faces.ply", header + body));
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[1], (Vec3{1, 0, 0}));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].name, "rgb(255,0,0)");
}

TEST_F(PlyImport, AsciiSquareWithFaceColours) {
  const std::string body =
      "0 0.25 0 0\n1 0.25 0 0\n1 0.25 1 0\n0 0.25 1 0\n0.5 0.25 -1 0\n"
      "2 0 1\n"
      "7 3 0 4 1 128 128 128\n"
      "7 4 0 1 2 3 255 0 0\n";
  expect_square(import_mesh(write("square.ply", square_header("ascii") + body)));
}

TEST_F(PlyImport, BinaryLittleEndianSquareWithFaceColours) {
  expect_square(
      import_mesh(write("square.ply", square_header("binary_little_endian") + square_body(true))));
}

TEST_F(PlyImport, BinaryBigEndianSquareWithFaceColours) {
  expect_square(
      import_mesh(write("square.PLY", square_header("binary_big_endian") + square_body(false))));
}

TEST_F(PlyImport, BinaryWithSmallIntegerTypesAndVertexIndexName) {
  // Positions as int16, list count uint16 with uint8 indices, CRLF header.
  const std::string header =
      "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 3\r\n"
      "property short x\r\nproperty short y\r\nproperty short z\r\n"
      "element face 1\r\nproperty list ushort uchar vertex_index\r\nend_header\r\n";
  Bytes b(true);
  for (std::int16_t v : {-2, 0, 0, 3, 0, 0, 0, 4, 0}) b.put(v);
  b.put(std::uint16_t{3}).put(std::uint8_t{0}).put(std::uint8_t{1}).put(std::uint8_t{2});
  const ImportedMesh mesh = import_mesh(write("small.ply", header + b.str()));
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[0], (Vec3{-2, 0, 0}));
  EXPECT_EQ(mesh.positions[2], (Vec3{0, 4, 0}));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.materials.at(0).name, "default");
}

TEST_F(PlyImport, TruncatedBinaryNamesFileWithoutLine) {
  const std::string full = square_header("binary_little_endian") + square_body(true);
  const fs::path path = write("cut.ply", full.substr(0, full.size() - 5));
  const std::string message = error_of(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("end of data"), std::string::npos) << message;
  // Cut inside the vertex block, where the element size check trips first.
  const fs::path short_path = write("short.ply", full.substr(0, square_header("x").size() + 40));
  EXPECT_EQ(error_of(short_path).rfind(short_path.string() + ": ", 0), 0u);
}

TEST_F(PlyImport, BadHeaderNamesItsLine) {
  const fs::path format = write("format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n");
  EXPECT_EQ(error_of(format).rfind(format.string() + ":2: ", 0), 0u) << error_of(format);

  const fs::path type = write("type.ply",
                              "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n"
                              "end_header\n0\n");
  EXPECT_EQ(error_of(type).rfind(type.string() + ":4: ", 0), 0u) << error_of(type);

  const fs::path magic = write("magic.ply", "solid cube\n");
  EXPECT_EQ(error_of(magic).rfind(magic.string() + ":1: ", 0), 0u);

  const fs::path unterminated = write("open.ply", "ply\nformat ascii 1.0\nelement vertex 3\n");
  EXPECT_EQ(error_of(unterminated).rfind(unterminated.string() + ":", 0), 0u);

  const fs::path no_z = write("noz.ply",
                              "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                              "property float y\nelement face 0\n"
                              "property list uchar int vertex_indices\nend_header\n0 0\n");
  EXPECT_EQ(error_of(no_z).rfind(no_z.string() + ":3: ", 0), 0u) << error_of(no_z);
}

TEST_F(PlyImport, BadAsciiBodyNamesItsLine) {
  const std::string header = square_header("ascii");  // 17 lines
  const std::string vertices = "0 0.25 0 0\n1 0.25 0 0\n1 0.25 1 0\n0 0.25 1 0\n0.5 0.25 -1 0\n";
  const fs::path word = write("word.ply", header + "0 0.25 0 0\n1 0.25 zero 0\n");
  EXPECT_EQ(error_of(word).rfind(word.string() + ":19: ", 0), 0u) << error_of(word);

  const fs::path index = write("index.ply", header + vertices +
                                                "2 0 1\n7 3 0 4 1 128 128 128\n"
                                                "7 4 0 1 9 3 255 0 0\n");
  EXPECT_EQ(error_of(index).rfind(index.string() + ":25: ", 0), 0u) << error_of(index);

  const fs::path two = write("two.ply", header + vertices + "2 0 1\n7 2 0 4 1 1 1\n");
  EXPECT_EQ(error_of(two).rfind(two.string() + ":24: ", 0), 0u) << error_of(two);

  const fs::path cut = write("cut.ply", header + vertices + "2 0 1\n7 3 0 4 1 128 128 128\n7 4");
  EXPECT_EQ(error_of(cut).rfind(cut.string() + ":25: ", 0), 0u) << error_of(cut);

  const fs::path colour = write("colour.ply", header + vertices + "2 0 1\n7 3 0 4 1 300 0 0\n");
  EXPECT_EQ(error_of(colour).rfind(colour.string() + ":24: ", 0), 0u) << error_of(colour);
}

TEST_F(PlyImport, NonFiniteVertexOrNoFacesIsAnError) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const fs::path nan = write("nan.ply", header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(error_of(nan).rfind(nan.string() + ":11: ", 0), 0u) << error_of(nan);

  const fs::path cloud = write("cloud.ply",
                               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\n0 0 0\n");
  EXPECT_THROW(import_mesh(cloud), InputError);
}

}  // namespace
}  // namespace relight
